"""Looks up a transform every second; the buffer also serves its frame graph."""
import rclpy
import tf2_ros
from rclpy.node import Node
from rclpy.qos import QoSProfile
from rclpy.time import Time
from tf2_ros.buffer_client import BufferClient


class FrameListener(Node):
    def __init__(self):
        super().__init__('frame_listener')
        self.tf_buffer = tf2_ros.Buffer(node=self)
        self.tf_listener = tf2_ros.TransformListener(self.tf_buffer, self,
                                                     qos=QoSProfile(depth=5))
        self.remote = BufferClient(self, 'tf2_buffer_server')
        self.timer = self.create_timer(1.0, self.on_timer)

    def on_timer(self):
        self.tf_buffer.lookup_transform('map', 'base_link', Time())


def main():
    rclpy.init()
    rclpy.spin(FrameListener())
