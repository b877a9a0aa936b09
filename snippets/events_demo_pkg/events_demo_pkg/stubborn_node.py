"""A node that is slow to stop: it can ignore Ctrl+C (SIGINT), and SIGTERM too.

Lesson 6.6 uses it to show what launch does when a process does not stop on
Ctrl+C: it waits `sigterm_timeout` seconds, sends SIGTERM, waits
`sigkill_timeout` more and sends SIGKILL.  Real nodes get stuck like this in
a blocking driver call or a long save.  With the defaults it stops on Ctrl+C
like every other node of the book.
"""
import signal

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions


class StubbornNode(Node):

    def __init__(self):
        super().__init__('stubborn_node')
        self.ignore_sigint = self.declare_parameter('ignore_sigint', False).value
        self.ignore_sigterm = self.declare_parameter('ignore_sigterm', False).value
        self.chunk = 0
        # A timer also makes the executor wake up regularly, so the Python
        # signal handlers below run within half a second of a signal.
        self.timer = self.create_timer(0.5, self.save_chunk)
        signal.signal(signal.SIGINT, self.on_sigint)
        signal.signal(signal.SIGTERM, self.on_sigterm)
        self.get_logger().info('Saving the map, one chunk every 0.5 s '
                               f'(ignore SIGINT: {self.ignore_sigint}, '
                               f'ignore SIGTERM: {self.ignore_sigterm})')

    def save_chunk(self):
        self.chunk += 1

    def on_sigint(self, signum, frame):
        if self.ignore_sigint:
            self.get_logger().warning('Got SIGINT: ignoring it, still saving the map')
            return
        raise KeyboardInterrupt

    def on_sigterm(self, signum, frame):
        if self.ignore_sigterm:
            self.get_logger().warning('Got SIGTERM: ignoring it too')
            return
        self.get_logger().info('Got SIGTERM: stopping, the map saved so far')
        raise KeyboardInterrupt


def main(args=None):
    # Our own handlers decide about SIGINT and SIGTERM, not rclpy's.
    rclpy.init(args=args, signal_handler_options=SignalHandlerOptions.NO)
    node = None
    try:
        node = StubbornNode()  # Ctrl+C may come while it starts: it is on the graph already
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # Ctrl+C or a launch shutting us down: a normal way to stop.
    finally:
        if node is not None:
            node.destroy_node()
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
