"""Logs the filtered scan of whichever filter runs."""
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import LaserScan


class ScanLogger(Node):
    def __init__(self):
        super().__init__('scan_logger')
        self.create_subscription(LaserScan, 'scan_filtered', self.on_scan, 10)
        self.create_publisher(LaserScan, 'scan', 10)

    def on_scan(self, msg):
        self.get_logger().info(str(len(msg.ranges)))


def main():
    rclpy.init()
    rclpy.spin(ScanLogger())
