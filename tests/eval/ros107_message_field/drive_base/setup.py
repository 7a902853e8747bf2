from setuptools import setup

package_name = 'drive_base'

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
            'driver = drive_base.driver:main',
            'uploader = drive_base.uploader:main',
            'distro_driver = drive_base.distro_cmd:main',
            'recorder = drive_base.stamps:main',
            'mission = drive_base.mission:main',
        ],
    },
)
