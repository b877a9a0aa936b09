"""A pretend object detector: subscribes to "image", publishes on "detections".

Detection runs on a timer at `detect_rate` results per second, each time on
the newest frame received; the result is the fraction of bright pixels in
a square at the centre of the image.
"""
import numpy as np
from rclpy.node import Node
from sensor_msgs.msg import Image
from std_msgs.msg import Float32

from tuning_demo_pkg.image_qos import declare_image_qos
from tuning_demo_pkg.spinning import run

BRIGHT = 200  # a pixel whose red value is above this counts as bright
SQUARE = 64  # pixels, side of the square looked at


class Detector(Node):

    def __init__(self):
        super().__init__('detector')
        rate = self.declare_parameter('detect_rate', 5.0).value
        qos = declare_image_qos(self)
        self.newest = None
        self.subscription = self.create_subscription(Image, 'image', self.keep_newest, qos)
        self.publisher = self.create_publisher(Float32, 'detections', 10)
        self.timer = self.create_timer(1.0 / rate, self.detect)
        self.get_logger().info(
            f'Detecting at {rate:.1f} Hz on "{self.subscription.topic_name}" '
            f'({qos.reliability.name.lower()}, depth {qos.depth})')

    def keep_newest(self, message: Image):
        self.newest = message

    def detect(self):
        if self.newest is None:
            return
        message, self.newest = self.newest, None
        pixels = np.frombuffer(message.data, dtype=np.uint8).reshape(
            message.height, message.width, 3)
        side = min(SQUARE, message.height, message.width)
        top, left = (message.height - side) // 2, (message.width - side) // 2
        red = pixels[top:top + side, left:left + side, 0]
        if red.size == 0:
            return
        bright = float(np.count_nonzero(red > BRIGHT)) / red.size
        self.publisher.publish(Float32(data=bright))
        self.get_logger().info(f'Bright fraction {bright:.3f}', throttle_duration_sec=1.0)


def main():
    run(Detector)


if __name__ == '__main__':
    main()
