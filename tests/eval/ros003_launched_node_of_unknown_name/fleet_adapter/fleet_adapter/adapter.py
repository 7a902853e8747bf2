"""The adapter's node is named after the fleet in its configuration file."""
import argparse

import rclpy
import yaml
from std_msgs.msg import String


def main(argv=None):
    parser = argparse.ArgumentParser()
    parser.add_argument('-c', '--config_file', required=True)
    args = parser.parse_args(argv)
    with open(args.config_file) as handle:
        fleet_name = yaml.safe_load(handle)['fleet_name']
    rclpy.init()
    node = rclpy.node.Node(fleet_name)
    # Relative names: '/lane_closure_requests' whatever the fleet is called.
    node.create_subscription(String, 'lane_closure_requests', print, 10)
    node.create_subscription(String, 'speed_limit_requests', print, 10)  # ROS003
    # Private: '/<fleet>/status', which depends on the name nobody knows here.
    node.create_publisher(String, '~/status', 10)
    rclpy.spin(node)
