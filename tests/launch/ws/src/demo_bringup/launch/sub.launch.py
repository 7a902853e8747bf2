from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    ld = LaunchDescription()
    ld.add_action(DeclareLaunchArgument('ns', default_value='default_ns'))
    ld.add_action(Node(package='demo_py', executable='talker', namespace=LaunchConfiguration('ns')))
    return ld
