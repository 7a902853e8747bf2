"""Starts two camera nodes in one process, both named 'camera'."""
import rclpy
from rclpy.executors import MultiThreadedExecutor
from sensor_msgs.msg import Image


def main():
    rclpy.init()
    left = rclpy.create_node('camera')  # ROS007
    right = rclpy.create_node('camera')  # ROS007
    left.create_publisher(Image, 'left/image', 10)
    right.create_publisher(Image, 'right/image', 10)
    executor = MultiThreadedExecutor()
    executor.add_node(left)
    executor.add_node(right)
    executor.spin()
    rclpy.shutdown()
