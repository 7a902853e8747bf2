"""Turns key presses into velocity commands."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node

SPEED = 0.2


class KeyboardTeleop(Node):

    def __init__(self):
        super().__init__('keyboard_teleop')
        self.cmd_pub = self.create_publisher(Twist, 'cmd_vel', 10)  # ROS001
        self.timer = self.create_timer(0.1, self.send)

    def send(self):
        msg = Twist()
        msg.linear.x = SPEED
        self.cmd_pub.publish(msg)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(KeyboardTeleop())
    rclpy.shutdown()
