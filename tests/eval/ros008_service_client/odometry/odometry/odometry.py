"""Wheel odometry: publishes odom and serves the odometer reset."""
import rclpy
from nav_msgs.msg import Odometry
from rclpy.node import Node
from std_srvs.srv import Empty


class WheelOdometry(Node):

    def __init__(self):
        super().__init__('wheel_odometry')
        self.odom_pub = self.create_publisher(Odometry, 'odom', 10)
        self.create_service(Empty, 'reset_odometry', self.on_reset)

    def on_reset(self, request, response):
        return response


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(WheelOdometry())
    rclpy.shutdown()
