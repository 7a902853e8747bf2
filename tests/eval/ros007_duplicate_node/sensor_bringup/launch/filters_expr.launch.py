"""The scan filter chosen by a Python expression over a launch argument (whisper_ros's stream switch)."""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import LaunchConfiguration, PythonExpression
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('filter', default_value='median'),
        DeclareLaunchArgument('fast', default_value='False'),
        # if= and unless= of one expression: exactly one of these runs.
        Node(package='lidar_tools', executable='filter_voxel', name='expr_filter', namespace='expr',
             condition=IfCondition(PythonExpression(["'", LaunchConfiguration('filter'), "' == 'voxel'"]))),
        Node(package='lidar_tools', executable='filter_median', name='expr_filter', namespace='expr',
             condition=UnlessCondition(PythonExpression(["'", LaunchConfiguration('filter'), "' == 'voxel'"]))),
        # Two different expressions may both hold: one name for two nodes.
        Node(package='lidar_tools', executable='filter_voxel', name='expr_cleaner', namespace='expr',  # ROS007
             condition=IfCondition(PythonExpression([LaunchConfiguration('fast')]))),
        Node(package='lidar_tools', executable='filter_median', name='expr_cleaner', namespace='expr',  # ROS007
             condition=IfCondition(PythonExpression(['not ', LaunchConfiguration('fast'), ' or True']))),
    ])
