"""Filters IMU samples, but reads the topic it writes: it eats its own output."""
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import Imu


class ImuFilter(Node):

    def __init__(self):
        super().__init__('imu_filter')
        self.out = self.create_publisher(Imu, 'imu', 10)
        self.create_subscription(Imu, 'imu', self.on_imu, 10)  # ROS002

    def on_imu(self, msg):
        self.out.publish(msg)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(ImuFilter())
    rclpy.shutdown()
