"""Forwards raw joystick messages to the bridge input: neither type the bridge may take."""
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import Joy


class Joystick(Node):

    def __init__(self):
        super().__init__('joystick')
        self.pub = self.create_publisher(Joy, 'cmd_vel_in', 10)  # ROS004
        self.create_subscription(Joy, 'joy', self.pub.publish, 10)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Joystick())
    rclpy.shutdown()
