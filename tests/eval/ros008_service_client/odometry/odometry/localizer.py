"""Fuses odometry; resets it through the service, and asks a pose service nobody serves."""
import rclpy
from nav_msgs.msg import Odometry
from rcl_interfaces.srv import GetParameters
from rclpy.node import Node
from std_srvs.srv import Empty, Trigger


class Localizer(Node):

    def __init__(self):
        super().__init__('localizer')
        self.create_subscription(Odometry, 'odom', self.on_odom, 10)
        self.reset_client = self.create_client(Empty, 'reset_odometry')
        self.relocalize_client = self.create_client(Trigger, 'relocalize')  # ROS008
        self.params_client = self.create_client(GetParameters, 'wheel_odometry/get_parameters')

    def on_odom(self, msg):
        if msg.pose.pose.position.x > 100.0:
            self.reset_client.call_async(Empty.Request())
            self.relocalize_client.call_async(Trigger.Request())


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Localizer())
    rclpy.shutdown()
