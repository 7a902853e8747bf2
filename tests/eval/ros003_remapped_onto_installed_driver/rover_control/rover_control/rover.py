"""Turns velocity commands into wheel commands; the joystick driver is an installed package."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from std_msgs.msg import Float64MultiArray


class Rover(Node):
    def __init__(self):
        super().__init__('rover')
        self.create_subscription(Twist, '/cmd_vel_intuitive', self.on_cmd, 1)
        self.create_subscription(Float64MultiArray, '/encoders', self.on_encoders, 1)
        self.wheels = self.create_publisher(Float64MultiArray, '/wheel_cmd', 1)
        self.last_ticks = []

    def on_cmd(self, msg):
        out = Float64MultiArray()
        out.data = [msg.linear.x - msg.angular.z, msg.linear.x + msg.angular.z]
        self.wheels.publish(out)

    def on_encoders(self, msg):
        self.last_ticks = list(msg.data)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Rover())
