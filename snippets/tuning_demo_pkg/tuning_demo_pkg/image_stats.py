"""Logs what the images on "image" look like: size, encoding and bytes."""
from rclpy.node import Node
from sensor_msgs.msg import Image

from tuning_demo_pkg.image_qos import declare_image_qos
from tuning_demo_pkg.spinning import run


class ImageStats(Node):

    def __init__(self):
        super().__init__('image_stats')
        qos = declare_image_qos(self)
        self.subscription = self.create_subscription(Image, 'image', self.log_size, qos)

    def log_size(self, message: Image):
        self.get_logger().info(
            f'Image {message.width}x{message.height} {message.encoding}: '
            f'{len(message.data)} bytes', throttle_duration_sec=1.0)


def main():
    run(ImageStats)


if __name__ == '__main__':
    main()
