from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='vehicle_ctrl', namespace='ctrl_pkg', executable='ctrl_node', name='ctrl_node'),
        Node(package='web_console', executable='console'),
    ])
