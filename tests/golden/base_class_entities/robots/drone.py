from geometry_msgs.msg import PoseStamped

from robots.base import RobotNode


class Drone(RobotNode):

    def __init__(self):
        super().__init__('drone')
        self.create_subscription(PoseStamped, 'goal', self.on_goal, 10)

    def on_goal(self, msg):
        self.goal = msg
