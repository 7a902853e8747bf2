"""Starts the scan pipeline; the filter got the logger's name when the block was copied."""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='lidar_tools', executable='scan_logger', name='lidar_pipeline'),  # ROS007
        Node(package='lidar_tools', executable='filter_median', name='lidar_pipeline'),  # ROS007
    ])
