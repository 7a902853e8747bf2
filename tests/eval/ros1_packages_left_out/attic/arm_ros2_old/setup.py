from setuptools import setup

setup(
    name='arm_ros2_old',
    version='0.3.0',
    packages=['arm_ros2_old'],
    data_files=[('share/arm_ros2_old', ['package.xml'])],
    entry_points={'console_scripts': ['markers = arm_ros2_old.markers:main']},
)
