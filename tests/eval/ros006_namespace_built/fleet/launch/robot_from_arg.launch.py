from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    # The robot's namespace is whatever the operator passes: not known here.
    return LaunchDescription([
        DeclareLaunchArgument('robot'),
        Node(package='fleet', executable='robot_agent', namespace=LaunchConfiguration('robot')),
    ])
