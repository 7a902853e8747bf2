from geometry_msgs.msg import Twist
from std_msgs.msg import String

from .base import RobotNode


class Rover(RobotNode):

    def __init__(self):
        super().__init__('rover', rate_hz=5.0)
        self.create_subscription(Twist, 'cmd_vel', self.on_cmd_vel, 10)

    def on_cmd_vel(self, msg):
        self.last_cmd = msg

    def on_tick(self):
        self.status_pub.publish(String(data='driving'))
