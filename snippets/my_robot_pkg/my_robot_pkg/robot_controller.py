"""A configurable robot controller: all of its settings are ROS parameters.

It declares typed parameters (a name, a loop rate, speed limits, a list of
enabled sensors and nested per-sensor settings), logs the values it got, and
then drives: it publishes a velocity command on "cmd_vel" that slows the
robot down as the filtered obstacle distance shrinks.
"""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from std_msgs.msg import Float32

# Settings of each sensor the controller knows about.  They become nested
# parameters such as "sensors.lidar.topic".
SENSOR_DEFAULTS = {
    'lidar': {'enabled': True, 'topic': 'scan', 'range_max': 12.0},
    'camera': {'enabled': False, 'topic': 'image_raw', 'range_max': 5.0},
}

STOP_DISTANCE = 1.0  # metres: closer than this, the robot stands still


class RobotController(Node):

    def __init__(self):
        super().__init__('robot_controller')
        # [START parameters]
        # The type of each parameter comes from its default value:
        # str, float, list of str.  A value of another type is rejected.
        self.robot_name = self.declare_parameter('robot_name', 'my_robot').value
        self.update_rate = self.declare_parameter('update_rate', 10.0).value
        self.max_linear_speed = self.declare_parameter('max_linear_speed', 0.5).value
        self.max_angular_speed = self.declare_parameter('max_angular_speed', 1.0).value
        self.enabled_sensors = self.declare_parameter(
            'enabled_sensors', ['lidar', 'camera']).value
        # Nested settings: a YAML file writes them as
        #   sensors:
        #     lidar:
        #       topic: scan
        # and the node sees the flat name "sensors.lidar.topic".
        self.sensors = {
            sensor: {
                key: self.declare_parameter(f'sensors.{sensor}.{key}', default).value
                for key, default in settings.items()
            }
            for sensor, settings in SENSOR_DEFAULTS.items()
        }
        # [END parameters]
        self.log_configuration()

        self.obstacle_distance = None
        self.create_subscription(Float32, 'distance_filtered', self.on_distance, 10)
        self.cmd_publisher = self.create_publisher(Twist, 'cmd_vel', 10)
        self.create_timer(1.0 / self.update_rate, self.control_loop)

    def log_configuration(self):
        log = self.get_logger()
        log.info(f'Robot "{self.robot_name}" starting with update_rate={self.update_rate} Hz')
        log.info(f'Speed limits: linear {self.max_linear_speed} m/s, '
                 f'angular {self.max_angular_speed} rad/s')
        log.info(f'Enabled sensors: {", ".join(self.enabled_sensors) or "none"}')
        for sensor, settings in self.sensors.items():
            values = ', '.join(f'{key}={value}' for key, value in settings.items())
            log.info(f'sensors.{sensor}: {values}')

    def on_distance(self, msg):
        self.obstacle_distance = msg.data

    def control_loop(self):
        # Full speed when the way is clear, slower as an obstacle gets close.
        speed = self.max_linear_speed
        if self.obstacle_distance is not None:
            room = max(0.0, self.obstacle_distance - STOP_DISTANCE)
            speed = min(self.max_linear_speed, 0.5 * room)
        command = Twist()
        command.linear.x = speed
        self.cmd_publisher.publish(command)
        self.get_logger().info(f'cmd_vel linear.x={speed:.2f} m/s',
                               throttle_duration_sec=1.0)


def main(args=None):
    rclpy.init(args=args)
    node = None
    try:
        node = RobotController()  # Ctrl+C may come while it starts: it is on the graph already
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        if node is not None:
            node.destroy_node()
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
