"""What every node of the arm shares: its name and the joint topic."""
from rclpy.node import Node

ARM_NODE_NAME = 'arm'
JOINT_TOPIC = 'arm/joint_commands'


class ArmNode(Node):
    def __init__(self, role_suffix=''):
        super().__init__(ARM_NODE_NAME + role_suffix)  # ROS007
        self.declare_parameter('rate', 50.0)
