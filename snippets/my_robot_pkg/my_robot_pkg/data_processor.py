"""Smooths the distance readings with a moving average.

Subscribes to "distance", republishes the average of the last few readings
on "distance_filtered" and logs both, so you can watch data arrive.
"""
from collections import deque

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from std_msgs.msg import Float32


class DataProcessor(Node):

    def __init__(self):
        super().__init__('data_processor')
        self.window_size = self.declare_parameter('window_size', 3).value
        self.readings = deque(maxlen=self.window_size)
        # [START pub_sub]
        self.subscription = self.create_subscription(
            Float32, 'distance', self.on_reading, 10)
        self.publisher = self.create_publisher(Float32, 'distance_filtered', 10)
        # [END pub_sub]
        self.get_logger().info(
            f'Averaging the last {self.window_size} readings from '
            f'"{self.subscription.topic_name}"')

    def on_reading(self, msg):
        self.readings.append(msg.data)
        average = sum(self.readings) / len(self.readings)
        self.publisher.publish(Float32(data=average))
        self.get_logger().info(f'Received {msg.data:.2f} m -> average {average:.2f} m')


def main(args=None):
    rclpy.init(args=args)
    node = None
    try:
        node = DataProcessor()  # Ctrl+C may come while it starts: it is on the graph already
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        if node is not None:
            node.destroy_node()
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
