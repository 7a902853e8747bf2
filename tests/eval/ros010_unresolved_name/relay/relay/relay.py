"""Relays between topics named on the command line: the analysis cannot know them."""
import sys

import rclpy
from rclpy.node import Node
from std_msgs.msg import String


def main():
    rclpy.init()
    source, target = sys.argv[1], sys.argv[2]
    node = Node('relay')
    pub = node.create_publisher(String, target, 10)  # ROS010
    node.create_subscription(String, source, pub.publish, 10)  # ROS010
    node.create_subscription(String, 'heartbeat', pub.publish, 10)
    rclpy.spin(node)
    rclpy.shutdown()
