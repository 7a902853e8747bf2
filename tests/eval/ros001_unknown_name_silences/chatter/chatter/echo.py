"""Prints any String topic given on the command line."""
import sys

import rclpy
from rclpy.node import Node
from std_msgs.msg import String


def main():
    rclpy.init()
    topic = sys.argv[1]
    node = Node('echo')
    node.create_subscription(String, topic, lambda msg: print(msg.data), 10)
    rclpy.spin(node)
    rclpy.shutdown()
