import rclpy
from rclpy.node import Node
from sensor_msgs.msg import Imu, Temperature

from sensor_pkg.topics import IMU_TOPIC
from . import topics


class ImuNode(Node):

    def __init__(self):
        super().__init__('imu_node')
        self.imu_pub = self.create_publisher(Imu, IMU_TOPIC, 10)
        self.temperature_pub = self.create_publisher(
            Temperature, topics.TEMPERATURE_TOPIC, 10)


def main(args=None):
    rclpy.init(args=args)
    node = ImuNode()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()
