from setuptools import setup

package_name = 'base_console'

setup(
    name=package_name,
    version='0.1.0',
    packages=[package_name],
    data_files=[('share/ament_index/resource_index/packages', ['resource/' + package_name]),
                ('share/' + package_name, ['package.xml'])],
    install_requires=['setuptools'],
    entry_points={
        'console_scripts': [
            'console = base_console.console:main',
            'fake_wheel_controller = base_console.fake_wheel_controller:main',
            'odom_logger = base_console.odom_logger:main',
        ],
    },
)
