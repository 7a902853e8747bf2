"""Logs the monitor's alerts and acknowledges them."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class AlertLogger(Node):

    def __init__(self):
        super().__init__('alert_logger')
        self.ack = self.create_publisher(String, 'alert_ack', 10)
        self.create_subscription(String, 'alerts', self.on_alert, 10)

    def on_alert(self, msg):
        self.get_logger().warning(msg.data)
        self.ack.publish(msg)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(AlertLogger())
    rclpy.shutdown()
