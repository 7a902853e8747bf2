"""Logs the chatter; the '~/' makes it listen on /chatter_logger/chatter instead."""
import rclpy
from std_msgs.msg import String

from .common import DemoNode


class ChatterLogger(DemoNode):
    def __init__(self):
        super().__init__('chatter_logger')
        self.create_subscription(String, '~/chatter', self.on_message, 10)  # ROS003
        self.create_subscription(String, 'chatter_relayed', self.on_message, 10)

    def on_message(self, msg):
        self.get_logger().info(msg.data)


def main():
    rclpy.init()
    rclpy.spin(ChatterLogger())
