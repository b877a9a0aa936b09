"""A pretend range sensor: publishes the distance to the nearest obstacle.

There is no hardware here.  The readings follow a slow wave so that the
numbers are easy to follow in the output while you learn.
"""
import math

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from std_msgs.msg import Float32


class SensorPublisher(Node):

    def __init__(self):
        super().__init__('sensor_publisher')
        # How many readings per second.  Change it with
        # `--ros-args -p publish_rate:=5.0` or from a launch file.
        self.publish_rate = self.declare_parameter('publish_rate', 2.0).value
        # A relative topic name ("distance", not "/distance") so that a
        # namespace set by a launch file applies to it.
        self.publisher = self.create_publisher(Float32, 'distance', 10)
        self.count = 0
        # [START timer]
        self.timer = self.create_timer(1.0 / self.publish_rate, self.publish_reading)
        self.get_logger().info(
            f'Publishing distance readings on "{self.publisher.topic_name}" '
            f'at {self.publish_rate:.1f} Hz')
        # [END timer]

    def publish_reading(self):
        # An obstacle that drifts between 1.5 m and 2.5 m.
        distance = 2.0 + 0.5 * math.sin(self.count / 2.0)
        self.count += 1
        # Log first, then publish: the reading's line comes before the subscriber's.
        self.get_logger().info(f'Reading #{self.count}: {distance:.2f} m')
        self.publisher.publish(Float32(data=distance))


def main(args=None):
    rclpy.init(args=args)
    node = None
    try:
        node = SensorPublisher()  # Ctrl+C may come while it starts: it is on the graph already
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl+C or a launch shutting us down: a normal way to stop.
    finally:
        if node is not None:
            node.destroy_node()
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
