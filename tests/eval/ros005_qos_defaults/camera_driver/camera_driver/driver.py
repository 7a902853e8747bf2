"""A camera driver: images as sensor data (best effort), status with a plain depth."""
import rclpy
from rclpy.node import Node
from rclpy.qos import QoSPresetProfiles, QoSProfile, QoSReliabilityPolicy, qos_profile_sensor_data
from sensor_msgs.msg import CameraInfo, Image
from std_msgs.msg import Float64, Header, String

from camera_driver import profiles


class CameraDriver(Node):

    def __init__(self):
        super().__init__('camera_driver')
        self.image_pub = self.create_publisher(Image, 'image_raw', qos_profile_sensor_data)
        self.info_pub = self.create_publisher(
            CameraInfo, 'camera_info', QoSPresetProfiles.SENSOR_DATA.value)
        self.status_pub = self.create_publisher(String, 'status', 10)
        self.calibration_pub = self.create_publisher(CameraInfo, 'calibration', profiles.latched())
        self.heartbeat_pub = self.create_publisher(Header, 'heartbeat', profiles.heartbeat_qos())
        exposure_qos = QoSProfile(
            depth=1, reliability=QoSReliabilityPolicy.RMW_QOS_POLICY_RELIABILITY_BEST_EFFORT)
        self.exposure_pub = self.create_publisher(Float64, 'exposure', exposure_qos)
        self.timer = self.create_timer(1 / 30, self.capture)

    def capture(self):
        self.image_pub.publish(Image())
        self.info_pub.publish(CameraInfo())
        self.exposure_pub.publish(Float64())
        self.heartbeat_pub.publish(Header())
        self.status_pub.publish(String(data='streaming'))


def main(args=None):
    rclpy.init(args=args)
    driver = CameraDriver()
    driver.calibration_pub.publish(CameraInfo())
    rclpy.spin(driver)
    rclpy.shutdown()
