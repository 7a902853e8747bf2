"""Takes commands of the type a parameter selects, and forwards them to the base."""
import rclpy
from rclpy.node import Node
from geometry_msgs.msg import Twist, TwistStamped

from cmd_bridge.command_types import COMMAND_TYPES


class CmdBridge(Node):

    def __init__(self):
        super().__init__('cmd_bridge', automatically_declare_parameters_from_overrides=True)
        in_type = COMMAND_TYPES[self.get_parameter('command_type').value]
        self.create_subscription(in_type, 'cmd_vel_in', self.on_command, 10)
        # Every type the navigation input may take disagrees with what the follower sends.
        self.create_subscription(in_type, 'cmd_vel_nav', self.on_command, 10)  # ROS004
        out_type = TwistStamped if self.get_parameter('stamped_out').value else Twist
        self.out = self.create_publisher(out_type, 'cmd_vel', 10)

    def on_command(self, msg):
        self.out.publish(msg)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(CmdBridge())
    rclpy.shutdown()
