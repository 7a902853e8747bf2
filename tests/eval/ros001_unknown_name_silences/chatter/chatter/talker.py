"""Publishes a chatter and a debug topic; only the chatter has a known subscriber."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Talker(Node):

    def __init__(self):
        super().__init__('talker')
        self.chatter_pub = self.create_publisher(String, 'chatter', 10)
        # Nothing names 'debug', but the echo node subscribes to a topic chosen
        # on the command line, which may be this one: no ROS001 here.
        self.debug_pub = self.create_publisher(String, 'debug', 10)
        self.timer = self.create_timer(1.0, self.on_timer)

    def on_timer(self):
        msg = String()
        msg.data = 'hello'
        self.chatter_pub.publish(msg)
        self.debug_pub.publish(msg)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Talker())
    rclpy.shutdown()
