"""A base class that gives every demo node its queue depth."""
from rclpy.node import Node


class DemoNode(Node):
    depth = 10

    def listen(self, topic, callback):
        from std_msgs.msg import String
        return self.create_subscription(String, topic, callback, self.depth)
