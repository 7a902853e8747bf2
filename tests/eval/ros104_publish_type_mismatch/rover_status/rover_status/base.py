"""The publishers every rover node has, created once in a base class."""
from rclpy.node import Node
from std_msgs.msg import Int32, String

LEVEL_TOPIC = 'battery_level'


class RoverNode(Node):

    def __init__(self, name):
        super().__init__(name)
        self.level_pub = self.create_publisher(Int32, LEVEL_TOPIC, 10)
        self.mode_pub = self.create_publisher(String, 'mode', 10)
