"""Logs the odometry of the wheel base."""
import rclpy
from nav_msgs.msg import Odometry
from rclpy.node import Node


class OdomLogger(Node):

    def __init__(self):
        super().__init__('odom_logger')
        self.declare_parameter('log_every', 10)
        self.sub = self.create_subscription(Odometry, 'odom', self.on_odom, 10)

    def on_odom(self, msg):
        self.get_logger().debug('odom')


def main():
    rclpy.init()
    rclpy.spin(OdomLogger())


if __name__ == '__main__':
    main()
