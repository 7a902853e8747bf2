from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='patrol', executable='drive', name='drive'),
        Node(package='patrol', executable='mission', name='patrol_mission'),
    ])
