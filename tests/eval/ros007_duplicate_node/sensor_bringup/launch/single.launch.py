"""Starts the voxel filter under the pipeline's filter name."""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='lidar_tools', executable='filter_voxel', name='scan_pipeline'),
    ])
