from setuptools import setup

package_name = 'fleet_adapter'

setup(
    name=package_name,
    version='0.1.0',
    packages=[package_name],
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        ('share/' + package_name + '/launch', ['launch/fleet.launch.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    entry_points={
        'console_scripts': [
            'adapter = fleet_adapter.adapter:main',
            'manage_lane = fleet_adapter.manage_lane:main',
        ],
    },
)
