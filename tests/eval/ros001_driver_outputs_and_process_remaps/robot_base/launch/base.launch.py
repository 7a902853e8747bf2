from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='robot_base', executable='driver',
             remappings=[('cmd_vel', '/robot/cmd_vel')]),
        Node(package='robot_apps', executable='monitor'),
        Node(package='robot_apps', executable='teleop'),
    ])
