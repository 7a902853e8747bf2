from setuptools import setup

package_name = 'arm_tools'

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
            'load_monitor = arm_tools.load_monitor:main',
            'tool_frames = arm_tools.tool_frames:main',
            'wrist_monitor = arm_tools.wrist_monitor:main',
        ],
    },
)
