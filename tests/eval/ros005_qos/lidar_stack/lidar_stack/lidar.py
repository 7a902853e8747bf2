"""A lidar driver publishing with the sensor-data preset (best effort)."""
import rclpy
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data
from sensor_msgs.msg import LaserScan


class Lidar(Node):

    def __init__(self):
        super().__init__('lidar')
        self.scan_pub = self.create_publisher(LaserScan, 'scan', qos_profile_sensor_data)
        self.timer = self.create_timer(0.1, self.publish_scan)

    def publish_scan(self):
        self.scan_pub.publish(LaserScan())


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Lidar())
    rclpy.shutdown()
