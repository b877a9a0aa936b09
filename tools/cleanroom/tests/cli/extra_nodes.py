"""More tiny rclpy nodes, for the `ros2 topic type|find` and `ros2 param
describe|delete|load` tests (sample_nodes.py holds the older verbs' nodes).

Run as `python extra_nodes.py KIND [--ros-args ...]`; prints `ready NAME`
once up and spins until SIGINT/SIGTERM.
"""
from __future__ import annotations

import signal
import sys

import rclpy
from rcl_interfaces.msg import FloatingPointRange, IntegerRange, ParameterDescriptor
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.parameter import Parameter
from std_msgs.msg import Int32, String


def described() -> Node:
    """Parameters with every part of a descriptor `ros2 param describe` shows."""
    node = Node('described')
    node.declare_parameter('speed', 1.5, ParameterDescriptor(
        description='Top speed in m/s',
        floating_point_range=[FloatingPointRange(from_value=0.0, to_value=3.0, step=0.5)]))
    node.declare_parameter('count', 3, ParameterDescriptor(
        description='How many', additional_constraints='Only odd numbers',
        integer_range=[IntegerRange(from_value=0, to_value=10, step=1)]))
    node.declare_parameter('frame', 'map', ParameterDescriptor(
        read_only=True, description='Fixed frame'))
    node.declare_parameter('combo', 2, ParameterDescriptor(
        read_only=True, description='d', additional_constraints='ac',
        integer_range=[IntegerRange(from_value=-1, to_value=4, step=0)]))
    node.declare_parameter('anything', 1, ParameterDescriptor(dynamic_typing=True))
    node.declare_parameter('dyn', None, ParameterDescriptor(dynamic_typing=True))
    node.declare_parameter('unset', Parameter.Type.INTEGER,
                           ParameterDescriptor(description='No default'))
    node.declare_parameter('names', ['a', 'b'])
    node.declare_parameter('flags', [True, False])
    node.declare_parameter('ints', [1, 2])
    node.declare_parameter('blob', [b'\x01', b'\x02'])
    return node


def open_node() -> Node:
    """Takes any parameter (undeclared ones too), but `fixed` and `combo` are read-only."""
    node = Node('open', allow_undeclared_parameters=True,
                automatically_declare_parameters_from_overrides=True)
    node.declare_parameter('declared', 5)
    node.declare_parameter('fixed', 5, ParameterDescriptor(read_only=True))
    node.declare_parameter('combo', 2, ParameterDescriptor(read_only=True))
    return node


def hidden_talker() -> Node:
    """Publishes on the hidden topic /_hid."""
    node = Node('hidden_talker')
    publisher = node.create_publisher(String, '_hid', 10)
    node.create_timer(0.2, lambda: publisher.publish(String(data='h')))
    return node


def int_talker() -> Node:
    """Publishes Int32 on /chatter, so the topic has two types next to the String talker."""
    node = Node('int_talker')
    publisher = node.create_publisher(Int32, 'chatter', 10)
    node.create_timer(0.2, lambda: publisher.publish(Int32(data=3)))
    return node


KINDS = {'described': described, 'open': open_node, 'hidden_talker': hidden_talker,
         'int_talker': int_talker}


def main() -> None:
    rclpy.init(args=sys.argv)
    signal.signal(signal.SIGTERM, lambda *_: rclpy.try_shutdown())
    node = KINDS[sys.argv[1]]()
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
