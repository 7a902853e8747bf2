import rclpy
from rclpy.node import Node
from sensor_msgs.msg import Imu, Temperature

import sensor_pkg.topics
from .topics import IMU_TOPIC as IMU


class LoggerNode(Node):

    def __init__(self):
        super().__init__('logger_node')
        self.create_subscription(Imu, IMU, self.on_imu, 10)
        self.create_subscription(
            Temperature, sensor_pkg.topics.TEMPERATURE_TOPIC,
            self.on_temperature, 10)

    def on_imu(self, msg):
        self.get_logger().info('imu: %s' % msg.header.frame_id)

    def on_temperature(self, msg):
        self.get_logger().info('temperature: %.1f' % msg.temperature)


def main(args=None):
    rclpy.init(args=args)
    node = LoggerNode()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()
