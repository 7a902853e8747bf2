"""Statistics and dump tools, each renamed by launch; each executable also creates a helper node."""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='lidar_tools', executable='scan_stats', name='front_stats'),
        Node(package='lidar_tools', executable='scan_dump', name='front_dump'),  # ROS007
    ])
