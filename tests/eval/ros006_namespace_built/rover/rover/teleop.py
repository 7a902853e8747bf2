"""Keyboard teleop; started with `ros2 run rover teleop`, so it runs in the root namespace."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class Teleop(Node):

    def __init__(self):
        super().__init__('teleop')
        self.cmd_pub = self.create_publisher(Twist, self.get_namespace() + '/cmd_vel', 10)  # ROS006
        self.timer = self.create_timer(0.1, self.send)

    def send(self):
        self.cmd_pub.publish(Twist())


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Teleop())
    rclpy.shutdown()
