import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    config = os.path.join(get_package_share_directory('robot_bringup'), 'config', 'lidar.yaml')
    return LaunchDescription([
        Node(package='lidar_driver', executable='scan_node', parameters=[config]),
        Node(package='obstacle_monitor', executable='monitor',
             parameters=[{'scan_topic': '/front/scan', 'stop_topic': '/safety/stop'}]),
        Node(package='obstacle_monitor', executable='stop_relay',
             parameters=[{'input': '/safety/stop'}]),
    ])
