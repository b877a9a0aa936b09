"""Executables for the launch_ros tests: one that exits at once, one lifecycle node."""
import sys


def noop():
    """Exit straight away: command-line tests only need the process to start."""
    sys.exit(0)


def lifecycle_talker():
    """A managed node that follows its state machine; `fail_configure` makes it refuse."""
    import rclpy
    from rclpy.executors import ExternalShutdownException
    from rclpy.lifecycle import LifecycleNode, TransitionCallbackReturn

    refuse = 'fail_configure' in rclpy.utilities.remove_ros_args(sys.argv)

    class Talker(LifecycleNode):
        def on_configure(self, state):
            if refuse:
                return TransitionCallbackReturn.FAILURE
            self.get_logger().info('configured')
            return TransitionCallbackReturn.SUCCESS

        def on_activate(self, state):
            self.get_logger().info('activated')
            return TransitionCallbackReturn.SUCCESS

    rclpy.init(args=sys.argv)
    node = Talker('lifecycle_talker')
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()
