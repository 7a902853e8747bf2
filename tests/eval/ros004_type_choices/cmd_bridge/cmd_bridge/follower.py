"""Follows a target: sends the target's pose where the bridge expects velocity commands."""
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import PoseStamped


class Follower(Node):

    def __init__(self):
        super().__init__('follower')
        self.pub = self.create_publisher(PoseStamped, 'cmd_vel_nav', 10)
        self.create_subscription(PoseStamped, 'target_pose', self.pub.publish, 10)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Follower())
    rclpy.shutdown()
