"""Watches the battery and says, with every reading, whether it is low.

It answers every battery state, not only changes, so that a node that starts
late, or a watchdog, learns the current answer within one reading.
"""
from rclpy.node import Node
from sensor_msgs.msg import BatteryState
from std_msgs.msg import Bool

from dock_watch_pkg.ranges import declare_double
from dock_watch_pkg.spinning import run


class BatteryMonitor(Node):

    def __init__(self):
        super().__init__('battery_monitor')
        # [START parameters]
        self.low_threshold = declare_double(
            self, 'low_threshold', 0.2, 0.05, 0.95,
            'Charge (0.0 to 1.0) at or below which the battery is low')
        # [END parameters]
        # [START interface]
        self.publisher = self.create_publisher(Bool, 'battery_low', 10)
        self.subscription = self.create_subscription(
            BatteryState, 'battery_state', self.judge, 10)
        # [END interface]
        self.low = None
        self.get_logger().info(f'Battery low at or below {self.low_threshold:.2f}')

    def judge(self, state: BatteryState):
        low = state.percentage <= self.low_threshold
        if low != self.low:
            self.get_logger().info(f'Battery {"LOW" if low else "ok"}: '
                                   f'charge {state.percentage:.2f}')
            self.low = low
        self.publisher.publish(Bool(data=low))


def main():
    run(BatteryMonitor)


if __name__ == '__main__':
    main()
