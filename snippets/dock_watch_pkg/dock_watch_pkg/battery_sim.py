"""A simulated battery: publishes its state at a fixed rate while it drains.

There is no hardware here.  The charge starts at `initial_charge` and drops
by `drain_per_second` every second, so a monitor has something to watch.
"""
from rclpy.node import Node
from sensor_msgs.msg import BatteryState

from dock_watch_pkg.ranges import declare_double
from dock_watch_pkg.spinning import run


class BatterySim(Node):

    def __init__(self):
        super().__init__('battery_sim')
        # [START parameters]
        self.publish_rate = declare_double(
            self, 'publish_rate', 2.0, 0.5, 50.0, 'Battery states per second (Hz)')
        self.charge = declare_double(
            self, 'initial_charge', 1.0, 0.0, 1.0, 'Charge at start, 0.0 (empty) to 1.0 (full)')
        self.drain_per_second = declare_double(
            self, 'drain_per_second', 0.01, 0.0, 0.5, 'Charge lost per second')
        # [END parameters]
        # [START interface]
        self.publisher = self.create_publisher(BatteryState, 'battery_state', 10)
        self.timer = self.create_timer(1.0 / self.publish_rate, self.publish_state)
        # [END interface]
        self.get_logger().info(f'Publishing on "{self.publisher.topic_name}" at '
                               f'{self.publish_rate:.1f} Hz, charge {self.charge:.2f}')

    def publish_state(self):
        self.charge = max(0.0, self.charge - self.drain_per_second / self.publish_rate)
        state = BatteryState(percentage=self.charge, voltage=11.0 + 1.6 * self.charge,
                             present=True)
        state.header.stamp = self.get_clock().now().to_msg()
        state.power_supply_status = BatteryState.POWER_SUPPLY_STATUS_DISCHARGING
        self.publisher.publish(state)


def main():
    run(BatterySim)


if __name__ == '__main__':
    main()
