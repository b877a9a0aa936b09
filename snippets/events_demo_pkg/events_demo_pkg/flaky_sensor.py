"""A pretend range sensor that warms up first and may lose its hardware.

Lesson 6.6 needs a node whose start-up takes a while (so that "the process
has started" and "the sensor is ready" are two different moments) and one
that dies on its own (so that launch has a process exit to react to).
With the defaults it never dies and stops cleanly on Ctrl+C.
"""
import math
import os

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from std_msgs.msg import Float32


class FlakySensor(Node):

    def __init__(self):
        super().__init__('flaky_sensor')
        self.publish_rate = self.declare_parameter('publish_rate', 2.0).value
        # Seconds of calibration before the first reading.
        self.warmup = self.declare_parameter('warmup', 1.0).value
        # Die (exit code 1) after this many readings; 0 means never.
        self.crash_after = self.declare_parameter('crash_after', 0).value
        self.publisher = self.create_publisher(Float32, 'distance', 10)
        self.count = 0
        self.get_logger().info(f'Calibrating for {self.warmup:.1f} s (pid {os.getpid()})')
        self.timer = self.create_timer(self.warmup, self.become_ready)

    def become_ready(self):
        self.timer.cancel()
        self.timer = self.create_timer(1.0 / self.publish_rate, self.publish_reading)
        self.get_logger().info(f'Sensor ready: publishing on "{self.publisher.topic_name}" '
                               f'at {self.publish_rate:.1f} Hz')

    def publish_reading(self):
        distance = 2.0 + 0.5 * math.sin(self.count / 2.0)
        self.count += 1
        self.publisher.publish(Float32(data=distance))
        self.get_logger().info(f'Reading #{self.count}: {distance:.2f} m')
        if self.crash_after and self.count >= self.crash_after:
            self.get_logger().error('Lost contact with the sensor hardware, exiting')
            raise SystemExit(1)


def main(args=None):
    rclpy.init(args=args)
    node = None
    try:
        node = FlakySensor()  # Ctrl+C may come while it starts: it is on the graph already
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl+C or a launch shutting us down: a normal way to stop.
    finally:
        if node is not None:
            node.destroy_node()
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
