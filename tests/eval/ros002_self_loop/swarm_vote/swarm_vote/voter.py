"""One robot's vote: every robot broadcasts its opinion on a bus all robots share, and counts the others'."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import Int32

VOTES = '/swarm/votes'


class Voter(Node):

    def __init__(self):
        super().__init__('voter')
        self.opinion = 0
        self.ballot = self.create_publisher(Int32, VOTES, 10)
        self.create_subscription(Int32, VOTES, self.on_vote, 10)
        self.create_timer(1.0, lambda: self.ballot.publish(Int32(data=self.opinion)))

    def on_vote(self, msg):
        self.opinion = max(self.opinion, msg.data)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Voter())
