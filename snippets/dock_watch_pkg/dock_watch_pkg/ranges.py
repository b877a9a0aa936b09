"""Parameter declarations with a range, so a node refuses a value outside it.

rclpy checks a value given at start (from a launch file or the command line)
against the descriptor's range: outside it, declaring the parameter fails and
the node stops with an error naming the parameter, instead of running with a
nonsense setting.
"""
from rcl_interfaces.msg import FloatingPointRange, ParameterDescriptor
from rclpy.node import Node


def declare_double(node: Node, name: str, default: float, low: float, high: float,
                   description: str) -> float:
    """Declare a double parameter limited to [low, high]; return its value."""
    descriptor = ParameterDescriptor(
        description=description,
        floating_point_range=[FloatingPointRange(from_value=low, to_value=high, step=0.0)])
    return node.declare_parameter(name, default, descriptor).value
