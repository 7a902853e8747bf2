from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='joy', executable='joy_node', name='joy'),
        Node(package='teleop_twist_joy', executable='teleop_node', name='teleop',
             parameters=[{'axis_linear.x': 1, 'scale_linear.x': 0.4}],
             remappings=[('/cmd_vel', '/cmd_vel_intuitive')]),
        Node(package='rover_control', executable='rover', name='rover'),
        Node(package='rover_control', executable='motor_driver', name='motor_driver'),
    ])
