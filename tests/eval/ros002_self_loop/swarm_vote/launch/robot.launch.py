from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    # One robot of the swarm; the operator starts one per robot with robot:=robot_N.
    robot = LaunchConfiguration('robot')
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='robot_0'),
        Node(package='swarm_vote', executable='voter', namespace=robot),
        Node(package='swarm_vote', executable='relay', namespace=robot),
    ])
