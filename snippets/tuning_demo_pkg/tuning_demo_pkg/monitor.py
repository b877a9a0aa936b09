"""Counts the results on "detections" and reports them once a second."""
from rclpy.node import Node
from std_msgs.msg import Float32

from tuning_demo_pkg.spinning import run


class Monitor(Node):

    def __init__(self):
        super().__init__('monitor')
        self.count = 0
        self.last = None
        self.subscription = self.create_subscription(Float32, 'detections', self.count_one, 10)
        self.timer = self.create_timer(1.0, self.report)

    def count_one(self, message: Float32):
        self.count += 1
        self.last = message.data

    def report(self):
        if self.last is None:
            self.get_logger().info('No detections yet')
            return
        self.get_logger().info(f'{self.count} detections in the last second, '
                               f'last {self.last:.3f}')
        self.count = 0


def main():
    run(Monitor)


if __name__ == '__main__':
    main()
