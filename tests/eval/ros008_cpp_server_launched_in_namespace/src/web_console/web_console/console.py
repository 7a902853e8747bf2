"""The browser console's bridge to the vehicle controller (a C++ node in /ctrl_pkg)."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import String
from std_srvs.srv import SetBool, Trigger

CTRL = '/ctrl_pkg'


class Console(Node):

    def __init__(self):
        super().__init__('web_console')
        self.enable = self.create_client(SetBool, CTRL + '/enable_state')
        self.calibrate = self.create_client(Trigger, f'{CTRL}/calibrat')  # ROS008
        self.modes = self.create_subscription(String, CTRL + '/drive_mode', self.on_mode, 10)
        self.request = self.create_publisher(String, CTRL + '/mode_request', 10)

    def on_mode(self, msg):
        self.get_logger().info(msg.data)


def main():
    rclpy.init()
    rclpy.spin(Console())
