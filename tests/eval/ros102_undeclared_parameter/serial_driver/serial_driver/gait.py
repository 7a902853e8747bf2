"""A node that declares most parameters by literal name and a few whose names come from the
command line: those may be any name, but a read one letter off a declared name is a slip."""
import sys

import rclpy
from rclpy.node import Node


class Gait(Node):
    def __init__(self, extra):
        super().__init__('gait')
        self.declare_parameter('auto_standup_on_start', True)
        self.declare_parameter('step_height_1', 0.04)
        for name in extra:
            self.declare_parameter(name, 0.0)
        self.standup = self.get_parameter('auto_standup_on_stat').value  # ROS102
        self.height = self.get_parameter('step_height_1').value
        self.second = self.get_parameter('step_height_2').value
        self.trim = self.get_parameter('leg_trim').value


def main():
    rclpy.init()
    rclpy.spin(Gait(sys.argv[1:]))
