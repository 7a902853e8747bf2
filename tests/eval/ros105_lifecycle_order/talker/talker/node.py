from rclpy.node import Node
from std_msgs.msg import String


class Talker(Node):
    def __init__(self, name='talker'):
        super().__init__(name)
        self.pub = self.create_publisher(String, 'chatter', 10)

    def add_heartbeat(self):
        self.create_timer(1.0, self.beat)

    def beat(self):
        self.pub.publish(String(data='alive'))


def make_talker(name):
    return Talker(name)
