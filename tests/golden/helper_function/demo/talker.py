import rclpy
from rclpy.node import Node
from std_msgs.msg import Int32, String

from .helpers import make_publisher


class Talker(Node):

    def __init__(self):
        super().__init__('talker')
        self.chatter_pub = make_publisher(self, 'chatter')
        self.counter_pub = make_publisher(self, 'counter', msg_type=Int32)
        self.count = 0
        self.create_timer(1.0, self.on_timer)

    def on_timer(self):
        self.count += 1
        self.chatter_pub.publish(String(data='hello'))
        self.counter_pub.publish(Int32(data=self.count))


def main(args=None):
    rclpy.init(args=args)
    node = Talker()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()
