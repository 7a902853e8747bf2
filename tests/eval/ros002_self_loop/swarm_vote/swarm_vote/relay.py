"""A robot's relay, launched in its namespace too, but on a relative name: it hears only itself."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import Int32


class Relay(Node):

    def __init__(self):
        super().__init__('relay')
        self.out = self.create_publisher(Int32, 'opinion', 10)
        self.create_subscription(Int32, 'opinion', self.out.publish, 10)  # ROS002


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Relay())
