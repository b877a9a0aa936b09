"""Tiny rclpy nodes for the `ros2 node|topic|param` tests.

Run as `python sample_nodes.py KIND [--ros-args ...]`; each node spins until
SIGINT/SIGTERM so the tests can stop it cleanly.
"""
from __future__ import annotations

import signal
import sys

import rclpy
from geometry_msgs.msg import Twist
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy
from std_msgs.msg import String


def talker() -> Node:
    node = Node('sensor_publisher')
    rate = node.declare_parameter('rate_hz', 10.0).value
    publisher = node.create_publisher(String, 'chatter', 10)
    count = [0]

    def tick() -> None:
        publisher.publish(String(data=f'hello {count[0]}'))
        count[0] += 1

    node.create_timer(1.0 / rate, tick)
    return node


def listener() -> Node:
    node = Node('listener')
    node.create_subscription(String, 'chatter', lambda msg: None, 10)
    node.create_subscription(Twist, 'cmd_vel', lambda msg: None, 10)
    return node


def twister() -> Node:
    """Publishes a nested message so echo's YAML nesting can be checked."""
    node = Node('twister')
    publisher = node.create_publisher(Twist, 'cmd_vel', 10)

    def tick() -> None:
        msg = Twist()
        msg.linear.x = 0.5
        msg.angular.z = -1.25
        publisher.publish(msg)

    node.create_timer(0.1, tick)
    return node


def params() -> Node:
    """The recorded `/param_dump` node: parameters straight from overrides."""
    return Node('param_dump', automatically_declare_parameters_from_overrides=True)


def layered() -> Node:
    node = Node('layered')
    node.declare_parameter('level', 1)
    node.declare_parameter('label', 'base')
    return node


def qos_publisher() -> Node:
    """Best-effort publisher on /qos_topic: half of the QoS mismatch of lesson 6.7."""
    node = Node('qos_publisher')
    qos = QoSProfile(depth=10, reliability=ReliabilityPolicy.BEST_EFFORT)
    publisher = node.create_publisher(String, 'qos_topic', qos)
    node.create_timer(0.1, lambda: publisher.publish(String(data='x')))
    return node


def qos_subscriber() -> Node:
    """Reliable subscription on /qos_topic: it never receives from the best-effort publisher."""
    node = Node('qos_subscriber')
    qos = QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE)
    node.create_subscription(String, 'qos_topic', lambda msg: None, qos)
    return node


def lonely_talker() -> Node:
    """Publishes on /lonely, which nobody subscribes to."""
    node = Node('lonely_talker')
    publisher = node.create_publisher(String, 'lonely', 10)
    node.create_timer(0.1, lambda: publisher.publish(String(data='anyone?')))
    return node


KINDS = {'talker': talker, 'listener': listener, 'twister': twister,
         'params': params, 'layered': layered, 'qos_publisher': qos_publisher,
         'qos_subscriber': qos_subscriber, 'lonely_talker': lonely_talker}


def main() -> None:
    rclpy.init(args=sys.argv)
    signal.signal(signal.SIGTERM, lambda *_: rclpy.try_shutdown())
    node = KINDS[sys.argv[1]]()
    # the tests wait for this line (and for a running daemon to list the node)
    print('ready', node.get_fully_qualified_name(), flush=True)
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
