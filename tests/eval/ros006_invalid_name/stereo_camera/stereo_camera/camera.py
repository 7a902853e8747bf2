"""A camera node whose node name and topic name rcl rejects at start-up."""
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import Image


class Camera(Node):

    def __init__(self):
        super().__init__('2nd_camera')  # ROS006
        self.image_pub = self.create_publisher(Image, 'camera//image', 10)  # ROS006


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Camera())
    rclpy.shutdown()
