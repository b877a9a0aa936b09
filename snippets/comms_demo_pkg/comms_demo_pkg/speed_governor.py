"""Keeps the robot under the speed limit it hears on "speed_limit".

Until a limit arrives the governor does not know how fast the robot may
drive, so it holds the robot still and says so every 2 s.  The parameter
`durability` picks the QoS durability policy of its subscription.
"""
import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import Float32

DURABILITY = {
    'volatile': DurabilityPolicy.VOLATILE,
    'transient_local': DurabilityPolicy.TRANSIENT_LOCAL,
}


class SpeedGovernor(Node):

    def __init__(self):
        super().__init__('speed_governor')
        durability = self.declare_parameter('durability', 'volatile').value
        if durability not in DURABILITY:
            raise ValueError(f"parameter 'durability' is {durability!r}; "
                             f"use one of {', '.join(DURABILITY)}")
        # [START subscription]
        qos = QoSProfile(depth=1, reliability=ReliabilityPolicy.RELIABLE,
                         durability=DURABILITY[durability])
        self.subscription = self.create_subscription(Float32, 'speed_limit', self.on_limit, qos)
        # [END subscription]
        self.limit = None
        self.timer = self.create_timer(2.0, self.warn_without_limit)

    def on_limit(self, msg: Float32):
        self.limit = msg.data
        self.get_logger().info(f'Speed limit {msg.data:.2f} m/s received')

    def warn_without_limit(self):
        if self.limit is None:
            self.get_logger().warn('No speed limit received yet; holding the robot still')


def main(args=None):
    rclpy.init(args=args)
    node = None
    try:
        node = SpeedGovernor()
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl+C or a launch shutting us down: a normal way to stop.
    finally:
        if node is not None:
            node.destroy_node()
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
