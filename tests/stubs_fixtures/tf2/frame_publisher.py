"""Broadcasts the robot's pose as a transform, plus one static sensor frame."""
import rclpy
from geometry_msgs.msg import TransformStamped
from rclpy.node import Node
from tf2_ros import StaticTransformBroadcaster, TransformBroadcaster


class FramePublisher(Node):
    def __init__(self):
        super().__init__('frame_publisher', namespace='robot1')
        self.broadcaster = TransformBroadcaster(self)
        self.static_broadcaster = StaticTransformBroadcaster(self)
        self.timer = self.create_timer(0.1, self.on_timer)

    def on_timer(self):
        t = TransformStamped()
        t.header.frame_id = 'odom'
        t.child_frame_id = 'base_link'
        self.broadcaster.sendTransform(t)


def main():
    rclpy.init()
    rclpy.spin(FramePublisher())
