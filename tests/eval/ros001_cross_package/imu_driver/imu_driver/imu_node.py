"""Reads the IMU and publishes its samples; the temperature topic has no consumer anywhere."""
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import Imu, Temperature

from imu_driver.topics import DATA_TOPIC


class ImuNode(Node):

    def __init__(self):
        super().__init__('imu_driver')
        self.data_pub = self.create_publisher(Imu, DATA_TOPIC, 50)
        self.temp_pub = self.create_publisher(Temperature, 'imu/temperature', 10)  # ROS001
        self.timer = self.create_timer(0.02, self.poll)

    def poll(self):
        self.data_pub.publish(Imu())
        self.temp_pub.publish(Temperature())


def main(args=None):
    rclpy.init(args=args)
    node = ImuNode()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()
