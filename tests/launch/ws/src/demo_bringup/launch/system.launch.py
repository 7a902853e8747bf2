from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription
from launch.conditions import IfCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node, PushRosNamespace, SetRemap
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    robot = LaunchConfiguration('robot')
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='r1'),
        DeclareLaunchArgument('with_relay', default_value='true'),
        GroupAction([
            PushRosNamespace(robot),
            SetRemap(src='unused_topic', dst='other'),
            Node(package='demo_py', executable='talker', name='speaker',
                 parameters=[PathJoinSubstitution([FindPackageShare('demo_bringup'), 'config', 'talker.yaml']),
                             {'rate': 1.0}]),
            Node(package='demo_py', executable='listener', remappings=[('heard', 'chatter')]),
        ]),
        Node(package='demo_py', executable='listener', namespace='plain',
             remappings=[('hear', 'chatter')]),
        Node(package='demo_py', executable='talkr'),
        Node(package='demo_cpp', executable='relay', name='relay-1',
             condition=IfCondition(LaunchConfiguration('with_relay'))),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(
                PathJoinSubstitution([FindPackageShare('demo_bringup'), 'launch', 'sub.launch.py'])),
            launch_arguments=[('ns', 'r2')]),
    ])
