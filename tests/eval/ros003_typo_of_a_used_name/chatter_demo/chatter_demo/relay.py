"""Relays the chatter under another name: a second, correctly spelt user of both topics."""
import rclpy
from std_msgs.msg import String

from .common import DemoNode
from .names import CHATTER, RELAYED


class Relay(DemoNode):
    def __init__(self):
        super().__init__('relay')
        self.pub = self.create_publisher(String, RELAYED, self.depth)
        self.listen(CHATTER, self.pub.publish)


def main():
    rclpy.init()
    rclpy.spin(Relay())
