"""Watches the arm's status and commands it; which status topic is set per deployment."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import Float64, String


class ArmMonitor(Node):

    def __init__(self):
        super().__init__('arm_monitor')
        self.declare_parameter('status_topic', 'arm_status')
        topic = self.get_parameter('status_topic').value
        self.create_subscription(String, topic, self.on_status, 10)
        self.command_pub = self.create_publisher(Float64, 'arm_command', 10)

    def on_status(self, msg):
        if msg.data != 'ok':
            self.command_pub.publish(Float64(data=0.0))


def main():
    rclpy.init()
    rclpy.spin(ArmMonitor())
