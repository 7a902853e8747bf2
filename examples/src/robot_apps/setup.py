from setuptools import find_packages, setup

package_name = 'robot_apps'

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
    description='Teleop, a dashboard and a Fibonacci action pair.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'teleop = robot_apps.teleop:main',
            'dashboard = robot_apps.dashboard:main',
            'fibonacci_server = robot_apps.fibonacci:server_main',
            'fibonacci_client = robot_apps.fibonacci:client_main',
        ],
    },
)
