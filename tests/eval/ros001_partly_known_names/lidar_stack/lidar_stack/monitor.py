"""Watches the driver: its status, its scans and a heartbeat it never sends."""
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import LaserScan
from std_msgs.msg import Header, String


class LidarMonitor(Node):

    def __init__(self):
        super().__init__('lidar_monitor')
        self.create_subscription(String, 'lidar/status', self.on_status, 10)
        self.create_subscription(LaserScan, '/scan', self.on_scan, 10)
        self.create_subscription(Header, 'lidar/heartbeat', self.on_heartbeat, 10)  # ROS003

    def on_status(self, msg):
        self.get_logger().info(msg.data)

    def on_scan(self, msg):
        self.get_logger().debug(str(len(msg.ranges)))

    def on_heartbeat(self, msg):
        self.get_logger().debug(msg.frame_id)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(LidarMonitor())
    rclpy.shutdown()
