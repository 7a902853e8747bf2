"""QoS given as a depth, as presets and as QoSProfile objects."""
import rclpy
from rclpy.node import Node
from rclpy.qos import (DurabilityPolicy, HistoryPolicy, QoSPresetProfiles,
                       QoSProfile, ReliabilityPolicy, qos_profile_sensor_data)
from sensor_msgs.msg import LaserScan
from std_msgs.msg import String


class QosDemo(Node):

    def __init__(self):
        super().__init__('qos_demo')
        self.create_publisher(LaserScan, 'scan', qos_profile_sensor_data)
        best_effort = QoSProfile(
            depth=5, reliability=ReliabilityPolicy.BEST_EFFORT)
        self.create_subscription(LaserScan, 'scan', self.on_scan, best_effort)
        latched = QoSProfile(
            history=HistoryPolicy.KEEP_LAST,
            depth=1,
            durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self.create_publisher(String, 'map_name', latched)
        self.create_subscription(
            String, 'map_name', self.on_map_name, qos_profile=latched)
        self.create_publisher(String, 'chatter', 10)
        self.create_subscription(
            LaserScan, 'scan_filtered', self.on_scan,
            QoSPresetProfiles.SENSOR_DATA.value)

    def on_scan(self, msg):
        self.get_logger().info('%d ranges' % len(msg.ranges))

    def on_map_name(self, msg):
        self.get_logger().info(msg.data)


def main(args=None):
    rclpy.init(args=args)
    node = QosDemo()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
