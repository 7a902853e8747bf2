from setuptools import find_packages, setup

package_name = 'robot_drivers'

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages',
         ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='flake8-rosgraph maintainers',
    maintainer_email='maintainers@flake8-rosgraph.invalid',
    description='Lidar, motor, camera (lifecycle) and battery drivers.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'lidar_driver = robot_drivers.lidar_driver:main',
            'motor_driver = robot_drivers.motor_driver:main',
            'camera_driver = robot_drivers.camera_driver:main',
            'battery_monitor = robot_drivers.battery_monitor:main',
        ],
    },
)
