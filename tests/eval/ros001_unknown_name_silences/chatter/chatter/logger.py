"""Logs the chatter to a file; its topic name is misspelt."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class ChatterLogger(Node):

    def __init__(self):
        super().__init__('chatter_logger')
        # The echo node's topic is unknown, but it cannot make 'chater' right: a slip of
        # 'chatter', which the talker publishes with the same type.
        self.create_subscription(String, 'chater', self.on_chatter, 10)  # ROS003
        self.lines = []

    def on_chatter(self, msg):
        self.lines.append(msg.data)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(ChatterLogger())
    rclpy.shutdown()
