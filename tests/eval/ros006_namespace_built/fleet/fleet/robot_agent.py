"""One robot's agent; the fleet launch file starts one per robot, each in its namespace."""
import rclpy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rclpy.node import Node

from fleet.topics import robot_topic


class RobotAgent(Node):

    def __init__(self):
        super().__init__('robot_agent')
        self.cmd_pub = self.create_publisher(Twist, self.get_namespace() + '/cmd_vel', 10)
        self.create_subscription(Odometry, robot_topic(self, 'odom'), self.on_odom, 10)

    def on_odom(self, msg):
        self.cmd_pub.publish(Twist())


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(RobotAgent())
    rclpy.shutdown()
