"""A pretend camera: publishes sensor_msgs/msg/Image frames on "image".

Every frame is drawn anew (a moving colour gradient), so a larger image or a
higher frame rate costs real CPU, as with a real driver converting frames.
"""
import array

import numpy as np
from rclpy.node import Node
from sensor_msgs.msg import Image

from tuning_demo_pkg.image_qos import declare_image_qos
from tuning_demo_pkg.spinning import run


class Camera(Node):

    def __init__(self):
        super().__init__('camera')
        self.width = self.declare_parameter('width', 1280).value
        self.height = self.declare_parameter('height', 720).value
        fps = self.declare_parameter('fps', 30.0).value
        qos = declare_image_qos(self)
        self.publisher = self.create_publisher(Image, 'image', qos)
        rows = np.arange(self.height, dtype=np.uint16)[:, None]
        columns = np.arange(self.width, dtype=np.uint16)[None, :]
        self.gradient = ((rows + columns) % 256).astype(np.uint8)
        self.frame = 0
        self.timer = self.create_timer(1.0 / fps, self.publish_frame)
        self.get_logger().info(
            f'Publishing {self.width}x{self.height} rgb8 images on '
            f'"{self.publisher.topic_name}" at {fps:.1f} fps '
            f'({qos.reliability.name.lower()}, depth {qos.depth})')

    def draw(self) -> np.ndarray:
        """The next frame: the gradient shifted by the frame number, per channel."""
        shifted = self.gradient + np.uint8(self.frame % 256)
        return np.dstack((shifted, shifted[::-1], 255 - shifted))

    def publish_frame(self):
        message = Image()
        message.header.stamp = self.get_clock().now().to_msg()
        message.header.frame_id = 'camera'
        message.height = self.height
        message.width = self.width
        message.encoding = 'rgb8'
        message.step = self.width * 3
        message.data = array.array('B', self.draw().tobytes())
        self.publisher.publish(message)
        self.frame += 1


def main():
    run(Camera)


if __name__ == '__main__':
    main()
