"""Controller: turns "drive to this point" into velocity commands.

A proportional controller: turn towards the goal in proportion to the
heading error, and drive in proportion to the distance, slowed down while
the turtle still faces away (nothing forward at all beyond 90 degrees).
It publishes ``cmd_vel`` ten times a second; the launch file remaps it to
``cmd_vel_nav``, so that the safety monitor, not the turtle, receives it.
"""
import math

from geometry_msgs.msg import Point, Twist
from rclpy.node import Node
from turtlesim.msg import Pose

from .running import run
from .world import normalize_angle


def clamp(value: float, limit: float) -> float:
    return max(-limit, min(limit, value))


class Controller(Node):

    def __init__(self):
        super().__init__('controller')
        self.max_linear = self.declare_parameter('max_linear', 1.0).value
        self.max_angular = self.declare_parameter('max_angular', 2.0).value
        self.k_linear = self.declare_parameter('k_linear', 1.0).value
        self.k_angular = self.declare_parameter('k_angular', 4.0).value
        self.goal_tolerance = self.declare_parameter('goal_tolerance', 0.1).value
        rate = self.declare_parameter('rate', 10.0).value
        self.pose = None
        self.goal = None
        self.create_subscription(Pose, 'estimated_pose', self.on_pose, 10)
        self.create_subscription(Point, 'goal', self.on_goal, 10)
        self.publisher = self.create_publisher(Twist, 'cmd_vel', 10)
        self.create_timer(1.0 / rate, self.steer)
        self.get_logger().info(f'Steering at {rate:.1f} Hz, at most {self.max_linear:.2f} m/s')

    def on_pose(self, pose: Pose):
        self.pose = pose

    def on_goal(self, goal: Point):
        self.goal = goal

    def steer(self):
        if self.pose is None or self.goal is None:
            return  # nothing to steer by yet
        dx, dy = self.goal.x - self.pose.x, self.goal.y - self.pose.y
        distance = math.hypot(dx, dy)
        command = Twist()
        if distance > self.goal_tolerance:
            error = normalize_angle(math.atan2(dy, dx) - self.pose.theta)
            forward = max(0.0, math.cos(error))
            command.linear.x = min(self.max_linear, self.k_linear * distance) * forward
            command.angular.z = clamp(self.k_angular * error, self.max_angular)
        self.publisher.publish(command)


def main(args=None):
    return run(Controller, args)


if __name__ == '__main__':
    main()
