import rclpy
from rclpy.node import Node
from std_msgs.msg import String

from . import helpers


class Listener(Node):

    def __init__(self):
        super().__init__('listener')
        helpers.make_subscription(self, String, 'chatter', self.on_chatter)

    def on_chatter(self, msg):
        self.get_logger().info(msg.data)


def main(args=None):
    rclpy.init(args=args)
    node = Listener()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()
