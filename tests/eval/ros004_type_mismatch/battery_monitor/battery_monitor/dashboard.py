"""Shows the battery level, but expects the wrong message and service types."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import Int32
from std_srvs.srv import Trigger


class Dashboard(Node):

    def __init__(self):
        super().__init__('dashboard')
        self.create_subscription(Int32, 'battery/level', self.on_level, 10)  # ROS004
        self.calibrate = self.create_client(Trigger, 'battery/calibrate')  # ROS004

    def on_level(self, msg):
        self.get_logger().info(f'battery at {msg.data}%')


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Dashboard())
    rclpy.shutdown()
