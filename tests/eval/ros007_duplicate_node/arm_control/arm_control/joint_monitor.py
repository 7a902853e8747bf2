"""Relays joint commands to the driver; its name was copied from the driver."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import Float64MultiArray

from .base import JOINT_TOPIC


class JointMonitor(Node):
    def __init__(self):
        super().__init__('arm')  # ROS007
        self.pub = self.create_publisher(Float64MultiArray, JOINT_TOPIC, 10)
        self.create_timer(0.1, self.tick)

    def tick(self):
        self.pub.publish(Float64MultiArray(data=[0.0] * 6))


def main():
    rclpy.init()
    rclpy.spin(JointMonitor())
