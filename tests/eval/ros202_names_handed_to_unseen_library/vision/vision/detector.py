"""A detector whose input is gated by an on/off filter from a library outside the workspace:
the library creates the subscription (and an 'image_raw/filter_state' service) on the node."""
import gated_io
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import Image
from std_msgs.msg import String

from vision.head_control import HeadControl


class Detector(Node):
    def __init__(self):
        super().__init__('detector')
        self.images = gated_io.OnOffSubscriber(self, Image, 'image_raw', self.on_image, 1)
        self.head = HeadControl(self, 'detector')
        self.results = self.create_publisher(String, 'detections', 10)
        self.create_subscription(String, 'mode', self.on_mode, 1)

    def on_image(self, msg):
        self.results.publish(String(data=f'{msg.width}x{msg.height}'))

    def on_mode(self, msg):
        self.get_logger().info(msg.data)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Detector())
