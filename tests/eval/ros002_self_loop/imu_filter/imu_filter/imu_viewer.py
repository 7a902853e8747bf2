"""Shows the filtered IMU samples."""
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import Imu


def main(args=None):
    rclpy.init(args=args)
    node = Node('imu_viewer')
    node.create_subscription(Imu, '/imu', lambda msg: node.get_logger().info(str(msg.linear_acceleration)), 10)
    rclpy.spin(node)
    rclpy.shutdown()
