"""Entity factories that work on whichever node they are given."""
from std_msgs.msg import String


def make_publisher(node, topic, msg_type=String, depth=10):
    return node.create_publisher(msg_type, topic, depth)


def make_subscription(node, msg_type, topic, callback):
    return node.create_subscription(msg_type, topic, callback, 10)
