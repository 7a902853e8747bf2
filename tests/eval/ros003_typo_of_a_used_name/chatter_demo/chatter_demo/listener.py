"""The first listener: spelt right, so the talker's topic stays in use after the recorder's typo."""
import rclpy

from .common import DemoNode
from .names import CHATTER


class Listener(DemoNode):
    def __init__(self):
        super().__init__('listener')
        self.listen(CHATTER, self.on_message)

    def on_message(self, msg):
        self.get_logger().info(msg.data)


def main():
    rclpy.init()
    rclpy.spin(Listener())
