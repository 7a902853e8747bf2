"""Topic names from the command line: unknown to a static analysis."""
import sys

import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Echo(Node):

    def __init__(self, topic):
        super().__init__('echo')
        self.echo_pub = self.create_publisher(String, topic + '_echo', 10)
        self.create_subscription(String, topic, self.on_message, 10)

    def on_message(self, msg):
        self.echo_pub.publish(msg)


def main():
    rclpy.init(args=sys.argv)
    node = Echo(sys.argv[1])
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
