"""Watches a laser scan for obstacles; which scan is a deployment choice."""
import rclpy
from rclpy.node import Node
from rclpy.parameter import Parameter
from sensor_msgs.msg import LaserScan
from std_msgs.msg import Bool


class ObstacleMonitor(Node):

    def __init__(self):
        super().__init__('obstacle_monitor')
        # No default in code: the launch file must say which scan to watch.
        self.declare_parameter('scan_topic', Parameter.Type.STRING)
        self.declare_parameter('stop_topic', 'obstacle_stop')
        scan_topic = self.get_parameter('scan_topic').value
        self.create_subscription(LaserScan, scan_topic, self.on_scan, 10)  # ROS003
        self.stop_pub = self.create_publisher(Bool, self.get_parameter('stop_topic').value, 10)

    def on_scan(self, msg):
        self.stop_pub.publish(Bool(data=min(msg.ranges, default=10.0) < 0.3))


def main():
    rclpy.init()
    rclpy.spin(ObstacleMonitor())
