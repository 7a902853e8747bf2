"""Publishes chatter for the listener, telemetry for the ground station, and a forgotten heartbeat."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Talker(Node):

    def __init__(self):
        super().__init__('talker')
        self.chatter_pub = self.create_publisher(String, 'chatter', 10)
        self.telemetry_pub = self.create_publisher(String, 'telemetry', 10)
        self.heartbeat_pub = self.create_publisher(String, 'heartbeat', 10)  # ROS001
        self.timer = self.create_timer(1.0, self.on_timer)

    def on_timer(self):
        msg = String()
        msg.data = 'alive'
        for pub in (self.chatter_pub, self.telemetry_pub, self.heartbeat_pub):
            pub.publish(msg)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Talker())
    rclpy.shutdown()
