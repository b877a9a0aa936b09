"""Spawner: asks turtlesim for one more turtle, then ends.

turtlesim starts with ``turtle1`` only; every further robot needs its own
turtle, made by turtlesim's ``/spawn`` service (the real turtlesim's and
the headless one's).  The turtle gets the name ``turtle_name`` (default:
the last part of the spawner's namespace) at ``x``, ``y``, ``theta``.
"""
import sys

import rclpy
from rclpy.executors import ExternalShutdownException
from turtlesim.srv import Spawn


def spawn(node, name: str, x: float, y: float, theta: float) -> None:
    client = node.create_client(Spawn, '/spawn')
    while not client.wait_for_service(timeout_sec=1.0):
        node.get_logger().info('Waiting for turtlesim (/spawn)', once=True)
    future = client.call_async(Spawn.Request(x=x, y=y, theta=theta, name=name))
    rclpy.spin_until_future_complete(node, future)
    if future.result().name:
        node.get_logger().info(f'Spawned {name} at ({x:.2f}, {y:.2f}), heading {theta:.2f}')
    else:  # turtlesim refuses a name that exists
        node.get_logger().warning(f'{name} exists already: using that turtle')


def main(args=None):
    rclpy.init(args=args)
    node = None
    try:
        node = rclpy.create_node('spawner')
        name = node.declare_parameter('turtle_name', '').value \
            or node.get_namespace().rstrip('/').rpartition('/')[2]
        if not name:
            node.get_logger().fatal('No turtle name: set turtle_name or start me in a namespace')
            return 1
        spawn(node, name, node.declare_parameter('x', 1.0).value,
              node.declare_parameter('y', 1.0).value, node.declare_parameter('theta', 0.0).value)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl+C or a launch shutting us down: a normal way to stop.
    finally:
        if node is not None:
            node.destroy_node()
        rclpy.try_shutdown()
    return 0


if __name__ == '__main__':
    sys.exit(main())
