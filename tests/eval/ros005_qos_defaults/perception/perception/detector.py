"""Detects objects in the driver's images."""
import copy

import rclpy
from rclpy.node import Node
from rclpy.qos import QoSPresetProfiles, ReliabilityPolicy, qos_profile_sensor_data
from sensor_msgs.msg import CameraInfo, Image
from std_msgs.msg import Float64


class Detector(Node):

    def __init__(self):
        super().__init__('detector')
        # A plain depth is reliable: the best-effort images never arrive.
        self.create_subscription(Image, 'image_raw', self.on_image, 10)  # ROS005
        self.create_subscription(
            CameraInfo, 'camera_info', self.on_info,
            QoSPresetProfiles.get_from_short_key('sensor_data'))
        # The operator picks the profile: unknown until run time.
        image_qos = self.declare_parameter('image_qos', 'services_default').value
        self.create_subscription(
            Image, 'image_raw', self.on_image, QoSPresetProfiles.get_from_short_key(image_qos))
        exposure_qos = copy.copy(qos_profile_sensor_data)
        exposure_qos.reliability = ReliabilityPolicy.RELIABLE
        self.create_subscription(Float64, 'exposure', self.on_exposure, exposure_qos)  # ROS005
        sensor_qos = copy.copy(qos_profile_sensor_data)
        sensor_qos.depth = 1
        self.create_subscription(Float64, 'exposure', self.on_exposure, sensor_qos)

    def on_image(self, msg):
        self.get_logger().debug('image %dx%d' % (msg.width, msg.height))

    def on_info(self, msg):
        self.get_logger().debug('camera info')

    def on_exposure(self, msg):
        self.get_logger().debug('exposure %f' % msg.data)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Detector())
    rclpy.shutdown()
