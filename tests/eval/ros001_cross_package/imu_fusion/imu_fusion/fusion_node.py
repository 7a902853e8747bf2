"""Consumes the IMU samples published by the imu_driver package."""
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import Imu


class FusionNode(Node):

    def __init__(self):
        super().__init__('imu_fusion')
        self.create_subscription(Imu, '/imu/data', self.on_imu, 50)
        self.samples = 0

    def on_imu(self, msg):
        self.samples += 1


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(FusionNode())
    rclpy.shutdown()
