import rclpy
from rclpy.node import Node

from serial_driver.base import SerialNode


class Passthrough(SerialNode):
    """Parameters come from a YAML file the launch file passes: all of them are declared."""

    def __init__(self):
        super().__init__('passthrough', automatically_declare_parameters_from_overrides=True)
        self.mode = self.get_parameter('mode').value


class Relay(Node):
    def __init__(self, topics):
        super().__init__('relay', allow_undeclared_parameters=True)
        for topic in topics:
            self.get_parameter(topic + '.qos')
        self.get_parameter('relay_rate')


class Plugins(Node):
    """Declares names read from a list it gets at run time: any name may be declared."""

    def __init__(self, plugins):
        super().__init__('plugins')
        for plugin in plugins:
            self.declare_parameter(plugin + '.enabled', True)
        self.get_parameter('lidar.enabled')


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Passthrough())
    rclpy.spin(Relay(['scan', 'odom']))
    rclpy.spin(Plugins(args))


def missing():
    node = rclpy.create_node('probe')
    node.declare_parameter('probe_rate', 2.0)
    return node.get_parameter('probe_rte').value  # ROS102
