from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='vision', executable='camera', name='camera'),
        Node(package='vision', executable='detector', name='detector',
             remappings=[('image_raw', '/camera/image_raw'),
                         ('image_raw/filter_state', 'detector/filter_state'),
                         ('pose/filter_state', 'head/filter_state')]),
    ])
