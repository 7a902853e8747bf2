from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='gnss_driver', executable='topic_driver', output='screen',
             parameters=[{'frame_id': 'gps'}]),
    ])
