import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Talker(Node):
    def __init__(self):
        super().__init__('talker')
        self.declare_parameter('rate', 2.0)
        self.pub = self.create_publisher(String, 'chatter', 10)


def main():
    rclpy.init()
    rclpy.spin(Talker())
