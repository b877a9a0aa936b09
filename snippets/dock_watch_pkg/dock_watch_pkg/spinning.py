"""Run one node until Ctrl+C or a launch shutting it down, then clean up."""
from collections.abc import Callable

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node


def run(factory: Callable[[], Node]) -> None:
    """Create the node and spin it; a stop by Ctrl+C or by launch is a normal end."""
    rclpy.init()
    node = None
    try:
        node = factory()  # a stop may come while it starts: it is on the graph already
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        if node is not None:
            node.destroy_node()
        rclpy.try_shutdown()
