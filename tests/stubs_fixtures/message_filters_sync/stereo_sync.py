"""Pairs camera images with their camera info and republishes the pair's stamp."""
import message_filters
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import CameraInfo, Image
from std_msgs.msg import Header


class StereoSync(Node):
    def __init__(self):
        super().__init__('stereo_sync')
        image_sub = message_filters.Subscriber(self, Image, 'camera/image_raw')
        info_sub = message_filters.Subscriber(self, CameraInfo, 'camera/camera_info',
                                              qos_profile=5)
        self.sync = message_filters.ApproximateTimeSynchronizer(
            [image_sub, info_sub], 10, 0.05)
        self.sync.registerCallback(self.on_pair)
        self.exact = message_filters.TimeSynchronizer([image_sub, info_sub], 10)
        self.exact.registerCallback(self.on_exact_pair)
        self.topic = image_sub.getTopic()

    def on_pair(self, image, info):
        self.stamp_pub = self.create_publisher(Header, 'paired_stamp', 10)

    def on_exact_pair(self, image, info):
        self.exact_pub = self.create_publisher(Header, self.topic + '/exact', 10)


def main():
    rclpy.init()
    rclpy.spin(StereoSync())
