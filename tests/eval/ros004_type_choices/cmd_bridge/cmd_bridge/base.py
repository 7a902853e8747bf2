"""The base takes plain Twist: one of the types the bridge may send, so no mismatch."""
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist


class Base(Node):

    def __init__(self):
        super().__init__('base')
        self.create_subscription(Twist, 'cmd_vel', self.on_cmd, 10)

    def on_cmd(self, msg):
        self.get_logger().info(str(msg.linear.x))


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Base())
    rclpy.shutdown()
