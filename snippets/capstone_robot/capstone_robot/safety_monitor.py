"""Safety monitor: the last node between the controller and the turtle.

Every command of the controller (``cmd_vel_nav``) passes through here on
its way to the turtle (``cmd_vel``).  Forward motion is cut when the wall
ahead is closer than ``stop_distance`` (turning stays allowed, so the
robot can turn away), and every motion is cut when the wall sensor has
been silent for ``sensor_timeout`` seconds: a blind robot stands still.
``safety_stop`` says whether a command is being held back.

A wall stop is released only when the wall is ``release_margin`` further
away than ``stop_distance`` (hysteresis): a robot stopped just inside the
limit would otherwise be let go by every noisy reading that lands just
outside it, and creep towards the wall.
"""
import time

from capstone_interfaces.msg import WallReading
from geometry_msgs.msg import Twist
from rclpy.node import Node
from std_msgs.msg import Bool

from .running import run


class SafetyMonitor(Node):

    def __init__(self):
        super().__init__('safety_monitor')
        self.stop_distance = self.declare_parameter('stop_distance', 0.8).value
        self.sensor_timeout = self.declare_parameter('sensor_timeout', 1.0).value
        self.release_margin = self.declare_parameter('release_margin', 0.1).value
        self.reading = None
        self.wall_close = False  # the wall ahead is within the limit: no forward motion
        self.limit = self.stop_distance  # the limit the latest reading was judged by
        self.reading_time = None
        self.reason = None  # why commands are held back now; None: they pass
        self.create_subscription(WallReading, 'wall_reading', self.on_reading, 10)
        self.create_subscription(Twist, 'cmd_vel_nav', self.on_command, 10)
        self.command_publisher = self.create_publisher(Twist, 'cmd_vel', 10)
        self.stop_publisher = self.create_publisher(Bool, 'safety_stop', 10)
        self.get_logger().info(f'Guarding: stop {self.stop_distance:.2f} m before a wall')

    def on_reading(self, reading: WallReading):
        self.reading = reading
        self.reading_time = time.monotonic()
        self.limit = self.stop_distance + (self.release_margin if self.wall_close else 0.0)
        self.wall_close = reading.ahead < self.limit

    def why_stop(self, command: Twist) -> str | None:
        """The reason to hold this command back, or None if it is safe."""
        if self.reading_time is None or time.monotonic() - self.reading_time > self.sensor_timeout:
            return f'no wall reading for {self.sensor_timeout:.1f} s'
        if command.linear.x > 0.0 and self.wall_close:
            return (f'wall {self.reading.ahead:.2f} m ahead '
                    f'(limit {self.limit:.2f} m)')
        return None

    def on_command(self, command: Twist):
        reason = self.why_stop(command)
        if reason is not None:
            if reason.startswith('wall'):
                command.linear.x = 0.0  # may still turn away from the wall
            else:
                command = Twist()  # blind: no motion at all
        if (reason is None) != (self.reason is None):  # log changes, not every command
            if reason is None:
                self.get_logger().info('Clear: commands pass again')
            else:
                self.get_logger().warning(f'Safety stop: {reason}')
        self.reason = reason
        self.command_publisher.publish(command)
        self.stop_publisher.publish(Bool(data=reason is not None))


def main(args=None):
    return run(SafetyMonitor, args)


if __name__ == '__main__':
    main()
