import os
from glob import glob

from setuptools import setup

package_name = 'swarm'

setup(
    name=package_name,
    version='0.1.0',
    packages=[package_name],
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        (os.path.join('share', package_name, 'launch'), glob('launch/*.launch.py')),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    entry_points={
        'console_scripts': [
            'lidar_layer = swarm.lidar_layer:main',
            'sonar_layer = swarm.sonar_layer:main',
        ],
    },
)
