"""Sends the robot to its dock when the battery turns low.

It publishes one goal (the dock's pose) each time the monitor's answer turns
from "ok" to "low", not with every reading, so a navigation stack gets a new
goal only when something changed.
"""
from geometry_msgs.msg import PoseStamped
from rclpy.node import Node
from std_msgs.msg import Bool

from dock_watch_pkg.ranges import declare_double
from dock_watch_pkg.spinning import run


class DockPlanner(Node):

    def __init__(self):
        super().__init__('dock_planner')
        # [START parameters]
        self.dock_x = declare_double(self, 'dock_x', 0.0, -100.0, 100.0, 'Dock position x (m)')
        self.dock_y = declare_double(self, 'dock_y', 0.0, -100.0, 100.0, 'Dock position y (m)')
        self.frame_id = self.declare_parameter('frame_id', 'map').value
        # [END parameters]
        # [START interface]
        self.publisher = self.create_publisher(PoseStamped, 'dock_goal', 10)
        self.subscription = self.create_subscription(Bool, 'battery_low', self.react, 10)
        # [END interface]
        self.low = None  # no report yet
        self.get_logger().info(f'Dock at ({self.dock_x:.1f}, {self.dock_y:.1f}) '
                               f'in frame {self.frame_id}; waiting for battery_low')

    def react(self, message: Bool):
        if self.low is None:  # the chain battery_sim -> monitor -> planner is connected
            self.get_logger().info(f'First report: battery {"low" if message.data else "ok"}')
        if message.data and not self.low:
            goal = PoseStamped()
            goal.header.stamp = self.get_clock().now().to_msg()
            goal.header.frame_id = self.frame_id
            goal.pose.position.x = self.dock_x
            goal.pose.position.y = self.dock_y
            goal.pose.orientation.w = 1.0
            self.publisher.publish(goal)
            self.get_logger().info(f'Battery low: heading to the dock at '
                                   f'({self.dock_x:.1f}, {self.dock_y:.1f})')
        elif not message.data and self.low:
            self.get_logger().info('Battery ok again')
        self.low = message.data


def main():
    run(DockPlanner)


if __name__ == '__main__':
    main()
