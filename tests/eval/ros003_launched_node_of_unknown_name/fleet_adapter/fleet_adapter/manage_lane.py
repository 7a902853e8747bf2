"""Closes a lane, and asks for a speed limit; the second topic name is misspelt."""
import rclpy
from std_msgs.msg import String


def main():
    rclpy.init()
    node = rclpy.create_node('manage_lane')
    closures = node.create_publisher(String, 'lane_closure_requests', 10)
    limits = node.create_publisher(String, 'speed_limit_request', 10)  # ROS001
    closures.publish(String(data='L1'))
    limits.publish(String(data='0.5'))
