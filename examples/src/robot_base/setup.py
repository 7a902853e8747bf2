from setuptools import find_packages, setup

package_name = 'robot_base'

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
    description='Shared names, QoS presets, a managed base node, helpers.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'heartbeat_monitor = robot_base.heartbeat_monitor:main',
        ],
    },
)
