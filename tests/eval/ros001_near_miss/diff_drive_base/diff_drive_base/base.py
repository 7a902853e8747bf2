"""Drives the wheels from velocity commands; the topic name has a typo."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class DiffDriveBase(Node):

    def __init__(self):
        super().__init__('diff_drive_base')
        self.create_subscription(Twist, 'cmdvel', self.on_cmd, 10)  # ROS003
        self.last = Twist()

    def on_cmd(self, msg):
        self.last = msg


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(DiffDriveBase())
    rclpy.shutdown()
