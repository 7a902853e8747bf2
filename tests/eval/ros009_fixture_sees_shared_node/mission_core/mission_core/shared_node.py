"""One node per process, shared by every state of a mission (a framework's singleton node)."""
from rclpy.node import Node


class SharedNode(Node):

    _instance = None

    def __init__(self):
        super().__init__('mission_node')

    @classmethod
    def get_instance(cls):
        if cls._instance is None:
            cls._instance = SharedNode()
        return cls._instance
