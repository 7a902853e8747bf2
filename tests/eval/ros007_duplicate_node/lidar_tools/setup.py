from setuptools import setup

package_name = 'lidar_tools'

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
            'filter_median = lidar_tools.filter_median:main',
            'filter_voxel = lidar_tools.filter_voxel:main',
            'scan_logger = lidar_tools.scan_logger:main',
            'scan_stats = lidar_tools.scan_stats:main',
            'scan_dump = lidar_tools.scan_stats:dump_main',
        ],
    },
)
