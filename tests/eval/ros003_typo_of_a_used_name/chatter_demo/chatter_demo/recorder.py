"""Records the chatter; its topic name has a dropped letter."""
import rclpy
from std_msgs.msg import String

from .common import DemoNode
from .names import RELAYED


class Recorder(DemoNode):
    def __init__(self):
        super().__init__('recorder')
        self.messages = []
        self.create_subscription(String, 'chater', self.messages.append, self.depth)  # ROS003
        self.create_subscription(String, RELAYED, self.messages.append, self.depth)


def main():
    rclpy.init()
    rclpy.spin(Recorder())
