"""A topic name with two possible values, chosen at run time."""
import os

import rclpy
from rclpy.node import Node
from sensor_msgs.msg import Image


class Mirror(Node):

    def __init__(self):
        super().__init__('mirror')
        use_sim = os.environ.get('USE_SIM') == '1'
        topic = 'sim/camera' if use_sim else 'camera'
        self.create_subscription(Image, topic, self.on_image, 10)
        self.mirrored_pub = self.create_publisher(Image, 'mirrored', 10)

    def on_image(self, msg):
        self.mirrored_pub.publish(msg)


def main(args=None):
    rclpy.init(args=args)
    node = Mirror()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
