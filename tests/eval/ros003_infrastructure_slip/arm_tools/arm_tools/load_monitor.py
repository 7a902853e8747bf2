"""Estimates the arm's load from the joint efforts that ros2_control's joint_state_broadcaster
publishes; 'joint_state' is a slip for '/joint_states', which no node of this workspace
publishes (its publisher is outside), so only its type and spelling give the slip away."""
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import JointState
from std_msgs.msg import Float64


class LoadMonitor(Node):

    def __init__(self):
        super().__init__('load_monitor')
        self.create_subscription(JointState, 'joint_state', self.on_joints, 10)  # ROS003
        self.load_pub = self.create_publisher(Float64, 'arm_load', 10)

    def on_joints(self, msg):
        self.load_pub.publish(Float64(data=sum(abs(e) for e in msg.effort)))


def main():
    rclpy.init()
    rclpy.spin(LoadMonitor())
