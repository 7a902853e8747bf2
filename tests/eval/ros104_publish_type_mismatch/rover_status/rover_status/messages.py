"""Message builders shared by the nodes."""
from std_msgs.msg import Int32, String


def mode_message(text):
    msg = String()
    msg.data = text
    return msg


def level_message(level):
    msg = Int32()
    msg.data = level
    return msg
