"""One scan filter or the other, chosen by a launch argument; the cleaner stage may run both."""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    voxel = LaunchConfiguration('voxel')
    return LaunchDescription([
        DeclareLaunchArgument('voxel', default_value='false'),
        DeclareLaunchArgument('median', default_value='true'),
        # Exactly one of these runs: one name is right.
        Node(package='lidar_tools', executable='filter_voxel', name='scan_filter',
             condition=IfCondition(voxel)),
        Node(package='lidar_tools', executable='filter_median', name='scan_filter',
             condition=UnlessCondition(voxel)),
        # Two different switches: with voxel:=true both run under one name.
        Node(package='lidar_tools', executable='filter_voxel', name='scan_cleaner',  # ROS007
             condition=IfCondition(voxel)),
        Node(package='lidar_tools', executable='filter_median', name='scan_cleaner',  # ROS007
             condition=IfCondition(LaunchConfiguration('median'))),
    ])
