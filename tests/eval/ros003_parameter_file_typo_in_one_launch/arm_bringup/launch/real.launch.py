import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    config = os.path.join(get_package_share_directory('arm_bringup'), 'config', 'real.yaml')
    return LaunchDescription([
        Node(package='arm_bringup', executable='arm_driver'),
        Node(package='arm_bringup', executable='arm_monitor', parameters=[config]),
    ])
