"""Stamped teleoperation commands: one of the types the bridge may take, so no mismatch."""
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import TwistStamped


class Teleop(Node):

    def __init__(self):
        super().__init__('teleop')
        self.pub = self.create_publisher(TwistStamped, 'cmd_vel_in', 10)
        self.timer = self.create_timer(0.1, lambda: self.pub.publish(TwistStamped()))


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Teleop())
    rclpy.shutdown()
