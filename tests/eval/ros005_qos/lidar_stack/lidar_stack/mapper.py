"""Subscribes reliably to the best-effort scan, and wants a latched map from a volatile publisher."""
import rclpy
from nav_msgs.msg import OccupancyGrid
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy, qos_profile_sensor_data
from sensor_msgs.msg import LaserScan

RELIABLE = QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE)
LATCHED = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)


class Mapper(Node):

    def __init__(self):
        super().__init__('mapper')
        self.create_subscription(LaserScan, 'scan', self.on_scan, RELIABLE)  # ROS005
        self.create_subscription(OccupancyGrid, 'map', self.on_map, LATCHED)  # ROS005
        self.create_subscription(LaserScan, 'scan', self.on_scan, qos_profile_sensor_data)

    def on_scan(self, msg):
        self.get_logger().debug('scan')

    def on_map(self, msg):
        self.get_logger().info('map received')


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Mapper())
    rclpy.shutdown()
