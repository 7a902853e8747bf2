"""A lidar driver: the scan and range topics come from the launch file, with defaults."""
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import LaserScan, PointCloud2, Range
from std_msgs.msg import String

from lidar_stack.params import topic_or_default


class LidarDriver(Node):

    def __init__(self):
        super().__init__('lidar_driver', automatically_declare_parameters_from_overrides=True)
        # '/scan' by default, else what the launch file says: the monitor's '/scan' is fed.
        self.scan_pub = self.create_publisher(
            LaserScan, topic_or_default(self, 'scan_topic', '/scan'), 10)
        # Nothing here subscribes '/range_debug', but the launch file may rename it to a
        # topic something does: a partly known name is never reported.
        self.range_pub = self.create_publisher(
            Range, topic_or_default(self, 'range_topic', '/range_debug'), 10)
        self.status_pub = self.create_publisher(String, 'lidar/status', 10)
        self.points_pub = self.create_publisher(PointCloud2, 'points_raw', 10)  # ROS001
        self.timer = self.create_timer(0.1, self.on_timer)

    def on_timer(self):
        self.scan_pub.publish(LaserScan())
        self.range_pub.publish(Range())
        self.status_pub.publish(String(data='ok'))
        self.points_pub.publish(PointCloud2())


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(LidarDriver())
    rclpy.shutdown()
