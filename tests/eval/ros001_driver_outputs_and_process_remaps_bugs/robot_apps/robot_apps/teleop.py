"""Drives the robot and shows the monitor's reports."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from std_msgs.msg import String


class Teleop(Node):
    def __init__(self):
        super().__init__('teleop')
        self.cmd = self.create_publisher(Twist, '/robot/cmd_vel', 1)  # ROS001
        self.create_subscription(String, '/summary', self.on_report, 1)
        self.create_subscription(String, '/stalls', self.on_report, 1)
        self.create_timer(0.1, lambda: self.cmd.publish(Twist()))

    def on_report(self, msg):
        self.get_logger().info(msg.data)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Teleop())
