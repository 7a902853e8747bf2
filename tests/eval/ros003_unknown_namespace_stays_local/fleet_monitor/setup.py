from setuptools import setup

package_name = 'fleet_monitor'

setup(
    name=package_name,
    version='0.1.0',
    packages=[package_name],
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    entry_points={
        'console_scripts': [
            'battery_driver = fleet_monitor.battery_driver:main',
            'odometry = fleet_monitor.odometry:main',
            'dashboard = fleet_monitor.dashboard:main',
        ],
    },
)
