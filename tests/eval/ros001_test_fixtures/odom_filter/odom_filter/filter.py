"""Smooths the wheel odometry; the output name has a typo its own test copied."""
import rclpy
from nav_msgs.msg import Odometry
from rclpy.node import Node

OUTPUT = 'odom_filterd'


class OdomFilter(Node):
    def __init__(self):
        super().__init__('odom_filter')
        self.declare_parameter('alpha', 0.3)
        self.pub = self.create_publisher(Odometry, OUTPUT, 10)  # ROS001
        self.create_subscription(Odometry, 'wheel/odom', self.on_odom, 10)

    def on_odom(self, msg):
        self.pub.publish(msg)


def main():
    rclpy.init()
    rclpy.spin(OdomFilter())
