from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    # One robot: its sensor layer is chosen by the operator, in the robot's namespace.
    sensor = LaunchConfiguration('sensor')
    return LaunchDescription([
        DeclareLaunchArgument('sensor'),
        DeclareLaunchArgument('robot', default_value='robot_0'),
        Node(package='swarm', executable=[sensor, '_layer'], namespace=LaunchConfiguration('robot')),
    ])
