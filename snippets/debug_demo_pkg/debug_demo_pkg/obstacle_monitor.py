"""Watches the robot's range sensors and says which of them it hears.

It subscribes to "range/<sensor>" (std_msgs/msg/Float32, reliable) for every
name in the parameter `sensors`, logs the first reading from each, and warns
about the sensors it has not heard from yet.  A sensor it never hears from is
the symptom this lesson starts from.
"""
import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy
from std_msgs.msg import Float32


class ObstacleMonitor(Node):

    def __init__(self):
        super().__init__('obstacle_monitor')
        sensors = self.declare_parameter('sensors', ['front']).value
        period = self.declare_parameter('check_period', 3.0).value
        # [START subscriptions]
        qos = QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE)
        self.heard = {}
        self.subscriptions_by_topic = {}
        for sensor in sensors:
            subscription = self.create_subscription(
                Float32, f'range/{sensor}',
                lambda msg, sensor=sensor: self.on_reading(sensor, msg), qos)
            self.subscriptions_by_topic[subscription.topic_name] = sensor
        # [END subscriptions]
        self.topics = {sensor: topic for topic, sensor in self.subscriptions_by_topic.items()}
        self.warned_about = None
        self.timer = self.create_timer(period, self.report_silent_sensors)
        self.get_logger().info(
            f'Watching {len(self.topics)} range sensors: {", ".join(self.topics.values())}')

    def on_reading(self, sensor, msg):
        if sensor not in self.heard:
            self.get_logger().info(
                f'First reading from "{self.topics[sensor]}": {msg.data:.2f} m')
        self.heard[sensor] = msg.data
        self.get_logger().debug(f'{sensor}: {msg.data:.2f} m')

    def report_silent_sensors(self):
        silent = [topic for sensor, topic in self.topics.items() if sensor not in self.heard]
        if silent == self.warned_about:
            return  # said it already
        self.warned_about = silent
        if silent:
            self.get_logger().warn(f'No readings yet from: {", ".join(silent)}')
        else:
            self.get_logger().info(f'All {len(self.topics)} sensors report')


def main(args=None):
    rclpy.init(args=args)
    node = None
    try:
        node = ObstacleMonitor()
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        if node is not None:
            node.destroy_node()
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
