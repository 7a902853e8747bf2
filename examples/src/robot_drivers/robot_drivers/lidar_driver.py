"""A (simulated) lidar: publishes laser scans with the sensor-data preset."""
import math

import rclpy
from sensor_msgs.msg import LaserScan

from robot_base.helpers import create_status_publisher
from robot_base.managed_node import ManagedNode
from robot_base.names import SCAN_TOPIC
from robot_base.qos import SCAN_QOS


class LidarDriver(ManagedNode):
    """Publishes ``/scan``; inherits the heartbeat from ManagedNode."""

    FRAME_ID = 'laser'
    BEAMS = 360

    def __init__(self) -> None:
        super().__init__('lidar_driver')
        self.declare_parameter('scan_rate', 10.0)
        rate = self.get_parameter('scan_rate').value
        self._scan_pub = self.create_publisher(LaserScan, SCAN_TOPIC, SCAN_QOS)
        self._status_pub = create_status_publisher(self)
        self._timer = self.create_timer(1.0 / rate, self.publish_scan)

    def publish_scan(self) -> None:
        scan = LaserScan()
        scan.header.stamp = self.get_clock().now().to_msg()
        scan.header.frame_id = self.FRAME_ID
        scan.angle_min = -math.pi
        scan.angle_max = math.pi
        scan.angle_increment = 2 * math.pi / self.BEAMS
        scan.range_min = 0.1
        scan.range_max = 12.0
        scan.ranges = [5.0] * self.BEAMS
        self._scan_pub.publish(scan)


def main(args=None):
    rclpy.init(args=args)
    node = LidarDriver()
    try:
        rclpy.spin(node)
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
