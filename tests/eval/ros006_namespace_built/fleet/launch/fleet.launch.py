from launch import LaunchDescription
from launch_ros.actions import Node

ROBOTS = ['robot1', 'robot2', 'robot3']


def generate_launch_description():
    return LaunchDescription([
        Node(package='fleet', executable='robot_agent', namespace=robot, name='agent')
        for robot in ROBOTS
    ])
