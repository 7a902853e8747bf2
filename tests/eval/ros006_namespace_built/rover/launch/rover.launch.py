from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    # One launch puts the driver in a namespace, the other leaves it at the root.
    return LaunchDescription([
        Node(package='rover', executable='driver', namespace='rover'),
        Node(package='rover', executable='mux'),
    ])
