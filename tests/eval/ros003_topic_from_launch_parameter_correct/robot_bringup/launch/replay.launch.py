from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    # Replays a recorded scan: which topic is chosen on the command line.
    return LaunchDescription([
        DeclareLaunchArgument('scan'),
        Node(package='obstacle_monitor', executable='monitor',
             parameters=[{'scan_topic': LaunchConfiguration('scan'), 'stop_topic': '/safety/stop'}]),
        Node(package='obstacle_monitor', executable='stop_relay',
             parameters=[{'input': '/safety/stop'}]),
    ])
