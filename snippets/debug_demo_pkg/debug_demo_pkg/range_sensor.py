"""A pretend range sensor for the debugging lesson: publishes distances on "range".

Two programs share this file.  `range_sensor` publishes std_msgs/msg/Float32,
the type the monitor expects.  `legacy_range_sensor` is the old driver that
still publishes std_msgs/msg/Float64 on the same topic name: start it by
mistake and nothing it sends is received, although the topic looks right.
"""
import math

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy
from std_msgs.msg import Float32, Float64

# [START reliability]
RELIABILITY = {
    'reliable': ReliabilityPolicy.RELIABLE,        # resend until received
    'best_effort': ReliabilityPolicy.BEST_EFFORT,  # send once, lose what is lost
}
# [END reliability]


class RangeSensor(Node):

    def __init__(self, message_type=Float32):
        super().__init__('range_sensor')
        self.message_type = message_type
        reliability = self.declare_parameter('reliability', 'reliable').value
        if reliability not in RELIABILITY:
            raise ValueError(f"parameter 'reliability' is {reliability!r}; "
                             f"use one of {', '.join(RELIABILITY)}")
        rate = self.declare_parameter('publish_rate', 5.0).value
        # [START publisher]
        qos = QoSProfile(depth=10, reliability=RELIABILITY[reliability])
        self.publisher = self.create_publisher(message_type, 'range', qos)
        # [END publisher]
        self.count = 0
        self.timer = self.create_timer(1.0 / rate, self.publish_reading)
        self.get_logger().info(
            f'Publishing {message_type.__name__} readings on "{self.publisher.topic_name}" '
            f'({reliability}) at {rate:.1f} Hz')

    def publish_reading(self):
        distance = 1.0 + 0.5 * math.sin(self.count / 3.0)
        self.count += 1
        self.publisher.publish(self.message_type(data=distance))
        # Shown only at log level debug: `--ros-args --log-level debug`.
        self.get_logger().debug(f'Published reading #{self.count}: {distance:.2f} m')


def run(message_type):
    rclpy.init()
    node = None
    try:
        node = RangeSensor(message_type)
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl+C or a launch shutting us down: a normal way to stop.
    finally:
        if node is not None:
            node.destroy_node()
        rclpy.try_shutdown()


def main():
    run(Float32)


def legacy_main():
    run(Float64)


if __name__ == '__main__':
    main()
