"""A command mux that builds its names from the namespace the safe ways."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node


class Mux(Node):

    def __init__(self):
        super().__init__('mux')
        ns = self.get_namespace()
        self.create_subscription(Twist, f"{ns.rstrip('/')}/cmd_vel_teleop", self.forward, 10)
        prefix = ns if ns != '/' else ''
        self.create_subscription(Twist, prefix + '/cmd_vel_nav', self.forward, 10)
        base = ns
        if base == '/':
            base = ''
        self.out_pub = self.create_publisher(Twist, base + '/cmd_vel', 10)
        self.create_publisher(Twist, ns + 'cmd_vel_out', 10)

    def forward(self, msg):
        self.out_pub.publish(msg)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Mux())
    rclpy.shutdown()
