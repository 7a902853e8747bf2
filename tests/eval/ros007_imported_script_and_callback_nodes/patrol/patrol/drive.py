"""Drives the base; also a small geometry helper that the mission imports."""
import math

import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


def yaw_from_quaternion(x, y, z, w):
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))


class Drive(Node):
    def __init__(self):
        super().__init__('drive')
        self.create_subscription(Twist, 'cmd_vel', self.on_cmd, 1)

    def on_cmd(self, msg):
        self.get_logger().info(f'{msg.linear.x}')


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Drive())


if __name__ == '__main__':
    main()
