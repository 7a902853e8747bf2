import rclpy
from nav_msgs.msg import Odometry
from rclpy.node import Node


class OdometryNode(Node):

    def __init__(self):
        super().__init__('odometry')
        self.odom_pub = self.create_publisher(Odometry, '/odom', 10)


def main():
    rclpy.init()
    rclpy.spin(OdometryNode())
