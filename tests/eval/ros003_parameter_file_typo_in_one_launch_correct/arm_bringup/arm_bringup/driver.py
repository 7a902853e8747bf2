"""Publishes the arm's status and reads its commands."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import Float64, String


class ArmDriver(Node):

    def __init__(self):
        super().__init__('arm_driver')
        self.status_pub = self.create_publisher(String, 'arm_status', 10)
        self.create_subscription(Float64, 'arm_command', self.on_command, 10)
        self.timer = self.create_timer(0.5, self.report)

    def on_command(self, msg):
        self.get_logger().info(f'command {msg.data}')

    def report(self):
        self.status_pub.publish(String(data='ok'))


def main():
    rclpy.init()
    rclpy.spin(ArmDriver())
