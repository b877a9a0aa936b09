"""Tells the robot how fast it may drive: publishes the speed limit on "speed_limit".

A limit changes rarely, so the server sends it once, at start-up, and again
only when someone changes the parameter `max_speed`
(`ros2 param set /limit_server max_speed 0.5`).  The parameter `durability`
picks the QoS durability policy of its publisher.
"""
import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import Float32

# [START durability]
DURABILITY = {
    'volatile': DurabilityPolicy.VOLATILE,
    'transient_local': DurabilityPolicy.TRANSIENT_LOCAL,
}
# [END durability]


class LimitServer(Node):

    def __init__(self):
        super().__init__('limit_server')
        self.declare_parameter('max_speed', 0.3)
        durability = self.declare_parameter('durability', 'volatile').value
        if durability not in DURABILITY:
            raise ValueError(f"parameter 'durability' is {durability!r}; "
                             f"use one of {', '.join(DURABILITY)}")
        # [START publisher]
        qos = QoSProfile(depth=1, reliability=ReliabilityPolicy.RELIABLE,
                         durability=DURABILITY[durability])
        self.publisher = self.create_publisher(Float32, 'speed_limit', qos)
        # [END publisher]
        # Publish again after `ros2 param set` has changed max_speed.
        self.add_post_set_parameters_callback(self.on_parameters_set)
        self.publish_limit()

    def publish_limit(self):
        limit = self.get_parameter('max_speed').value
        self.publisher.publish(Float32(data=float(limit)))
        self.get_logger().info(f'Published speed limit {limit:.2f} m/s')

    def on_parameters_set(self, parameters: list[Parameter]):
        if any(parameter.name == 'max_speed' for parameter in parameters):
            self.publish_limit()


def main(args=None):
    rclpy.init(args=args)
    node = None
    try:
        node = LimitServer()
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl+C or a launch shutting us down: a normal way to stop.
    finally:
        if node is not None:
            node.destroy_node()
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
