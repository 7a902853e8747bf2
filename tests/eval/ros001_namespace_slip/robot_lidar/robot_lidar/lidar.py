"""A lidar driver started in the robot's namespace: its relative 'scan' becomes /robot1/scan."""
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import LaserScan


class Lidar(Node):

    def __init__(self):
        super().__init__('lidar', namespace='robot1')
        self.scan_pub = self.create_publisher(LaserScan, 'scan', 10)  # ROS001
        self.timer = self.create_timer(0.1, self.publish_scan)

    def publish_scan(self):
        self.scan_pub.publish(LaserScan())


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Lidar())
    rclpy.shutdown()
