"""Shared base of the robot's sensor drivers: every output topic is a parameter."""
from rclpy.node import Node


class SensorNode(Node):

    def output_topic(self, parameter, default):
        self.declare_parameter(parameter, default)
        return self.get_parameter(parameter).get_parameter_value().string_value
