"""Feeds the filter and checks its output: the fixture uses the filter's own (misspelt) name."""
import rclpy
from nav_msgs.msg import Odometry

from odom_filter.filter import OUTPUT, OdomFilter


def test_filter_forwards_odometry():
    rclpy.init()
    under_test = OdomFilter()
    fixture = rclpy.create_node('odom_filter_fixture')
    feed = fixture.create_publisher(Odometry, 'wheel/odom', 10)
    received = []
    fixture.create_subscription(Odometry, OUTPUT, received.append, 10)
    feed.publish(Odometry())
    rclpy.spin_once(under_test, timeout_sec=0.1)
    fixture.destroy_node()
    rclpy.shutdown()
