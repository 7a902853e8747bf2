"""Publishes the tool frames for robot_state_publisher's tree; 'tf_statics' is a slip for
'/tf_static'."""
import rclpy
from geometry_msgs.msg import TransformStamped
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile
from tf2_msgs.msg import TFMessage


class ToolFrames(Node):

    def __init__(self):
        super().__init__('tool_frames')
        latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self.static_pub = self.create_publisher(TFMessage, 'tf_statics', latched)  # ROS001
        self.live_pub = self.create_publisher(TFMessage, 'tf', 10)
        self.timer = self.create_timer(1.0, self.send)

    def send(self):
        frame = TransformStamped()
        frame.header.frame_id = 'tool0'
        frame.child_frame_id = 'gripper'
        self.static_pub.publish(TFMessage(transforms=[frame]))
        self.live_pub.publish(TFMessage(transforms=[frame]))


def main():
    rclpy.init()
    rclpy.spin(ToolFrames())
