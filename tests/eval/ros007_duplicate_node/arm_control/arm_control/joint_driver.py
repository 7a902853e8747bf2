"""Drives the joints from the commands the monitor relays."""
import rclpy
from std_msgs.msg import Float64MultiArray

from .base import ArmNode, JOINT_TOPIC


class JointDriver(ArmNode):
    def __init__(self):
        super().__init__()
        self.create_subscription(Float64MultiArray, JOINT_TOPIC, self.on_command, 10)

    def on_command(self, msg):
        self.get_logger().info(f'{len(msg.data)} joints')


def main():
    rclpy.init()
    rclpy.spin(JointDriver())
