"""Helpers that create entities on a node they are given.

Drivers report their state the same way, so the publisher is made here once
instead of being repeated in every driver.
"""
from rclpy.node import Node
from rclpy.publisher import Publisher
from std_msgs.msg import String


def create_status_publisher(node: Node, topic: str = '~/status') -> Publisher:
    """Create the String publisher ``node`` reports its state on.

    The default is a private name, so each node gets ``/<node name>/status``.
    """
    return node.create_publisher(String, topic, 10)
