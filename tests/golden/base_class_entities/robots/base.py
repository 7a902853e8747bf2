"""The base class of all robots: status publisher, tick timer, frame prefix."""
from rclpy.node import Node
from std_msgs.msg import String


class RobotNode(Node):

    def __init__(self, name, rate_hz=2.0):
        super().__init__(name)
        self.declare_parameter('frame_prefix', name)
        self.status_pub = self.create_publisher(String, 'status', 10)
        self.create_timer(1.0 / rate_hz, self.on_tick)

    def on_tick(self):
        self.status_pub.publish(String(data='ok'))
