from setuptools import setup

package_name = 'cmd_bridge'

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
            'bridge = cmd_bridge.bridge:main',
            'teleop = cmd_bridge.teleop:main',
            'joystick = cmd_bridge.joystick:main',
            'base = cmd_bridge.base:main',
            'follower = cmd_bridge.follower:main',
        ],
    },
)
