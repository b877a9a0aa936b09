"""Wall sensor: a pretend range sensor, computed from the turtle's pose.

turtlesim has no range sensor, so this node plays one: from each pose it
works out the distance to the nearest wall and to the wall straight ahead,
adds a little measurement noise, and publishes a WallReading at its own
rate, as a real sensor driver would.
"""
import random

from capstone_interfaces.msg import WallReading
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data
from turtlesim.msg import Pose

from .running import run
from .world import WORLD_SIZE, distance_ahead, wall_distances


class WallSensor(Node):

    def __init__(self):
        super().__init__('wall_sensor')
        self.world_size = self.declare_parameter('world_size', WORLD_SIZE).value
        publish_rate = self.declare_parameter('publish_rate', 10.0).value
        self.noise_stddev = self.declare_parameter('noise_stddev', 0.0).value
        self.pose = None
        # Best effort: accepts a pose publisher of any reliability (the real turtlesim's too).
        self.create_subscription(Pose, 'pose', self.on_pose, qos_profile_sensor_data)
        self.publisher = self.create_publisher(WallReading, 'wall_reading', 10)
        self.create_timer(1.0 / publish_rate, self.publish_reading)
        self.get_logger().info(f'Measuring walls of a {self.world_size:.2f} m world '
                               f'at {publish_rate:.1f} Hz')

    def on_pose(self, pose: Pose):
        self.pose = pose

    def noisy(self, distance: float) -> float:
        return max(0.0, distance + random.gauss(0.0, self.noise_stddev))

    def publish_reading(self):
        if self.pose is None:
            return  # no turtle yet: nothing to measure
        walls = wall_distances(self.pose.x, self.pose.y, self.world_size)
        nearest = min(walls, key=walls.get)
        ahead = distance_ahead(self.pose.x, self.pose.y, self.pose.theta, self.world_size)
        self.publisher.publish(WallReading(nearest=self.noisy(walls[nearest]),
                                           nearest_wall=nearest, ahead=self.noisy(ahead)))


def main(args=None):
    return run(WallSensor, args)


if __name__ == '__main__':
    main()
