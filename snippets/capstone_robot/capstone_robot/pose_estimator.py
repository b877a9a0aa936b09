"""Pose estimator: smooths the turtle's pose before anyone steers by it.

A real robot's position comes from noisy odometry or localisation; a
filter between the measurement and the planner keeps a single bad sample
from jerking the robot around.  This one is an exponential filter: each
new pose moves the estimate by ``smoothing`` (1.0: no filtering) of the way.
"""
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data
from turtlesim.msg import Pose

from .running import ConfigurationError, run
from .world import normalize_angle


class PoseEstimator(Node):

    def __init__(self):
        super().__init__('pose_estimator')
        self.smoothing = self.declare_parameter('smoothing', 0.5).value
        publish_rate = self.declare_parameter('publish_rate', 20.0).value
        if not 0.0 < self.smoothing <= 1.0:
            raise ConfigurationError(f'smoothing must be in (0, 1], got {self.smoothing}')
        self.estimate = None
        self.create_subscription(Pose, 'pose', self.on_pose, qos_profile_sensor_data)
        self.publisher = self.create_publisher(Pose, 'estimated_pose', 10)
        self.create_timer(1.0 / publish_rate, self.publish_estimate)
        self.get_logger().info(f'Estimating the pose with smoothing {self.smoothing:.2f}')

    def on_pose(self, pose: Pose):
        if self.estimate is None:
            self.estimate = pose  # the first measurement is the best guess there is
            return
        a, est = self.smoothing, self.estimate
        est.x += a * (pose.x - est.x)
        est.y += a * (pose.y - est.y)
        est.theta = normalize_angle(est.theta + a * normalize_angle(pose.theta - est.theta))
        est.linear_velocity = pose.linear_velocity
        est.angular_velocity = pose.angular_velocity

    def publish_estimate(self):
        if self.estimate is not None:
            self.publisher.publish(self.estimate)


def main(args=None):
    return run(PoseEstimator, args)


if __name__ == '__main__':
    main()
