"""Counts, once with print() and once with the ROS logger, to show output buffering.

Python writes print() output straight away only when standard output is a
terminal.  Under `ros2 launch` it is a pipe, so Python collects the text
in a buffer of several kilobytes and writes it when the buffer is full or
the program ends.  The ROS logger writes to standard error, which is never
held back.  Lesson 6.1 runs this node both ways.
"""
import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node


class PrintCounter(Node):

    def __init__(self):
        super().__init__('print_counter')
        self.count = 0
        self.timer = self.create_timer(0.5, self.tick)

    # [START tick]
    def tick(self):
        self.count += 1
        print(f'{self.get_name()} printed tick {self.count}')  # standard output
        self.get_logger().info(f'logged tick {self.count}')   # standard error
    # [END tick]


def main(args=None):
    rclpy.init(args=args)
    node = None
    try:
        node = PrintCounter()  # Ctrl+C may come while it starts: it is on the graph already
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        if node is not None:
            node.destroy_node()
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
