"""The QoS of the image topic, from two parameters every image node declares.

`reliability` and `depth` are parameters (not code) so that they can be
changed from a launch file and measured before and after.
"""
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy

RELIABILITY = {
    'reliable': ReliabilityPolicy.RELIABLE,        # resend until received
    'best_effort': ReliabilityPolicy.BEST_EFFORT,  # send once, lose what is lost
}


def declare_image_qos(node: Node) -> QoSProfile:
    """Declare `reliability` and `depth` on `node` and return the QoS they describe."""
    reliability = node.declare_parameter('reliability', 'reliable').value
    if reliability not in RELIABILITY:
        raise ValueError(f"parameter 'reliability' is {reliability!r}; "
                         f"use one of {', '.join(RELIABILITY)}")
    depth = node.declare_parameter('depth', 100).value
    if depth < 1:
        raise ValueError(f"parameter 'depth' is {depth}; use 1 or more")
    return QoSProfile(depth=depth, reliability=RELIABILITY[reliability])
