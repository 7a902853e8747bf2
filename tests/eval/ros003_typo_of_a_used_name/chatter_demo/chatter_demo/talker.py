"""Publishes a greeting twice a second."""
import rclpy
from std_msgs.msg import String

from .common import DemoNode
from .names import CHATTER


class Talker(DemoNode):
    def __init__(self):
        super().__init__('talker')
        self.pub = self.create_publisher(String, CHATTER, self.depth)
        self.create_timer(0.5, self.tick)

    def tick(self):
        self.pub.publish(String(data='hello'))


def main():
    rclpy.init()
    rclpy.spin(Talker())
