from setuptools import setup

setup(
    name='arm_ros2',
    version='0.3.0',
    packages=['arm_ros2'],
    data_files=[('share/arm_ros2', ['package.xml'])],
    entry_points={'console_scripts': ['markers = arm_ros2.markers:main']},
)
