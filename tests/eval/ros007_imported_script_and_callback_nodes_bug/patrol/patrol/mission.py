"""Runs a patrol mission; uses the drive module's geometry helper only."""
import rclpy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rclpy.node import Node

from patrol.drive import yaw_from_quaternion


class Mission(Node):
    def __init__(self):
        super().__init__('mission')
        self.cmd = self.create_publisher(Twist, 'cmd_vel', 1)
        self.create_subscription(Odometry, 'odom', self.on_odom, 1)

    def on_odom(self, msg):
        # a throw-away node per message: the launch file's name is given to it as well
        probe = rclpy.create_node('odom_probe')
        probe.destroy_node()
        q = msg.pose.pose.orientation
        twist = Twist()
        twist.angular.z = -0.5 * yaw_from_quaternion(q.x, q.y, q.z, q.w)
        self.cmd.publish(twist)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Mission())


if __name__ == '__main__':
    main()
