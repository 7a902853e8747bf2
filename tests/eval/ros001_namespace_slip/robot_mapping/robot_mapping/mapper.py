"""Builds a map from laser scans, but listens on the global /scan."""
import rclpy
from nav_msgs.msg import OccupancyGrid
from rclpy.node import Node
from sensor_msgs.msg import LaserScan


class Mapper(Node):

    def __init__(self):
        super().__init__('mapper')
        self.create_subscription(LaserScan, '/scan', self.on_scan, 10)  # ROS003
        self.map_pub = self.create_publisher(OccupancyGrid, 'map', 1)

    def on_scan(self, msg):
        self.map_pub.publish(OccupancyGrid())


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Mapper())
    rclpy.shutdown()
