"""Run nodes until Ctrl+C or a launch shutting them down, then clean up."""
from collections.abc import Callable

import rclpy
from rclpy.executors import ExternalShutdownException, SingleThreadedExecutor
from rclpy.node import Node


def run(*factories: Callable[[], Node]) -> None:
    """Create the nodes (all in this one process) and spin them together."""
    rclpy.init()
    nodes = []
    executor = SingleThreadedExecutor()
    try:
        for factory in factories:
            nodes.append(factory())
            executor.add_node(nodes[-1])
        executor.spin()
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl+C or a launch shutting us down: a normal way to stop.
    finally:
        executor.shutdown()
        for node in nodes:
            node.destroy_node()
        rclpy.try_shutdown()
