"""Watches the driver: wants latched status and calibration, and a lively heartbeat."""
import rclpy
from rclpy.duration import Duration
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, LivelinessPolicy, QoSProfile
from sensor_msgs.msg import CameraInfo
from std_msgs.msg import Header, String


class Monitor(Node):

    LATCHED = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)

    def __init__(self):
        super().__init__('monitor')
        self.create_subscription(String, 'status', self.on_status, self.LATCHED)  # ROS005
        self.create_subscription(String, 'status', self.on_status, 10)
        self.create_subscription(CameraInfo, 'calibration', self.on_calibration, self.LATCHED)
        strict = QoSProfile(depth=1, deadline=Duration(seconds=0.5))
        self.create_subscription(Header, 'heartbeat', self.on_heartbeat, strict)  # ROS005
        relaxed = QoSProfile(depth=1, deadline=Duration(seconds=2),
                             liveliness_lease_duration=Duration(seconds=3))
        self.create_subscription(Header, 'heartbeat', self.on_heartbeat, relaxed)
        manual = QoSProfile(depth=1, liveliness=LivelinessPolicy.MANUAL_BY_TOPIC)
        self.create_subscription(Header, 'heartbeat', self.on_heartbeat, manual)  # ROS005

    def on_status(self, msg):
        self.get_logger().info(msg.data)

    def on_calibration(self, msg):
        self.get_logger().info('calibrated')

    def on_heartbeat(self, msg):
        self.get_logger().debug('alive')


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Monitor())
    rclpy.shutdown()
