"""Starts the median filter under the same name: an alternative to single.launch.py, never run with it."""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='lidar_tools', executable='filter_median', name='scan_pipeline'),
    ])
