"""Builders for the messages the driver sends."""
from geometry_msgs.msg import Twist


def make_twist(linear, angular):
    cmd = Twist()
    cmd.linear.x = linear  # ROS107
    cmd.angular.z = angular
    return cmd


def make_stop():
    cmd = Twist()
    cmd.linear.x = 0.0
    cmd.angular.z = 0.0
    return cmd
