"""Velocity commands for two ROS distributions: Humble takes Twist, later ones TwistStamped."""
import os

import rclpy
from rclpy.node import Node

if os.environ.get('ROS_DISTRO', 'humble') == 'humble':
    from geometry_msgs.msg import Twist as CmdVel
else:
    from geometry_msgs.msg import TwistStamped as CmdVel
from geometry_msgs.msg import Twist

STAMPED = os.environ.get('ROS_DISTRO', 'humble') != 'humble'


def turn(speed):
    twist = Twist()
    twist.angular.z = speed
    return twist


class DistroDriver(Node):

    def __init__(self):
        super().__init__('distro_driver')
        self.pub = self.create_publisher(CmdVel, 'cmd_vel', 10)
        self.create_timer(0.1, self.on_tick)

    def on_tick(self):
        twist = turn(0.5)
        if STAMPED:
            stamped = CmdVel()  # a TwistStamped on this path, never a Twist
            stamped.header.stamp = self.get_clock().now().to_msg()
            stamped.twist = twist
            self.pub.publish(stamped)
        else:
            self.pub.publish(twist)
        stop = CmdVel()
        stop.linaer.x = 0.0  # ROS107
        stop.header.frame_id = 'base_link'  # only TwistStamped has a header: unknown here, quiet


def main():
    rclpy.init()
    rclpy.spin(DistroDriver())
