"""Uploads a calibration: which calibrator runs is chosen at start-up, and the upload follows it."""
import rclpy
from rclpy.node import Node
from sensor_msgs.srv import SetCameraInfo
from std_msgs.msg import Float32

from drive_base.calibrators import MonoCalibrator, StereoCalibrator


class Uploader(Node):

    def __init__(self):
        super().__init__('calibration_uploader')
        self.calibrator = None
        self.create_subscription(Float32, 'camera/count', self.on_count, 10)
        self.set_info = self.create_client(SetCameraInfo, 'camera/set_camera_info')
        self.set_left = self.create_client(SetCameraInfo, 'left/set_camera_info')
        self.gain_pub = self.create_publisher(Float32, 'camera/gain', 10)
        self.create_timer(1.0, self.upload)

    def on_count(self, msg):
        if self.calibrator is None:
            if msg.data > 1.0:
                self.calibrator = StereoCalibrator((640, 480))
            else:
                self.calibrator = MonoCalibrator((640, 480))

    def upload(self):
        if self.calibrator is None:
            return
        info = self.calibrator.as_message()
        request = SetCameraInfo.Request()
        if self.calibrator.is_mono:
            request.camera_info = info  # a CameraInfo here, never the stereo pair: quiet
            self.set_info.call_async(request)
        else:
            request.camera_info = info[0]
            self.set_left.call_async(request)
        self.publish_gain(2.5)
        self.publish_gain(1)

    def publish_gain(self, gain):
        msg = Float32()
        msg.data = gain  # ROS107
        self.gain_pub.publish(msg)


def main():
    rclpy.init()
    rclpy.spin(Uploader())
