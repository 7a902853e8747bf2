"""Drives the planner with a fake odometry source: a fixture of this package only."""
import rclpy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry

from local_planner.planner import LocalPlanner


def test_planner_commands_the_base():
    rclpy.init()
    planner = LocalPlanner()
    fake = rclpy.create_node('fake_odometry')
    odom = fake.create_publisher(Odometry, 'odom_filtered', 10)
    commands = []
    fake.create_subscription(Twist, 'cmd_vel', commands.append, 10)
    odom.publish(Odometry())
    rclpy.spin_once(planner, timeout_sec=0.1)
    rclpy.shutdown()
