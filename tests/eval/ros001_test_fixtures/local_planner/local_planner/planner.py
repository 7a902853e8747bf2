"""Plans from the filtered odometry and drives the base."""
import rclpy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rclpy.node import Node


class LocalPlanner(Node):
    def __init__(self):
        super().__init__('local_planner')
        self.cmd = self.create_publisher(Twist, 'cmd_vel', 10)
        self.create_subscription(Odometry, 'odom_filtered', self.on_odom, 10)  # ROS003

    def on_odom(self, msg):
        self.cmd.publish(Twist())


def main():
    rclpy.init()
    rclpy.spin(LocalPlanner())
