from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    use_fake = LaunchConfiguration('use_fake_hardware')
    return LaunchDescription([
        DeclareLaunchArgument('use_fake_hardware', default_value='false'),
        # The real controller (C++) and its stand-in get the same parameters.
        Node(package='wheel_base', executable='wheel_controller', namespace='base',
             parameters=[{'wheel_radius': 0.05, 'publish_rate': 50.0}],
             condition=UnlessCondition(use_fake)),
        Node(package='base_console', executable='fake_wheel_controller', namespace='base',
             parameters=[{'wheel_radius': 0.05, 'publish_rate': 50.0}],
             condition=IfCondition(use_fake)),
        Node(package='wheel_base', executable='wheel_calibrator', namespace='base'),
        Node(package='wheel_base', executable='wheel_calibrater', namespace='base'),  # ROS201
        Node(package='battery_driver', executable='battery_node', namespace='power'),
        Node(package='base_console', executable='console'),
        # A typo in a parameter of an analysed node that no stand-in shares is still one.
        Node(package='base_console', executable='odom_logger', namespace='base',  # ROS204
             parameters=[{'log_evry': 5}]),
    ])
