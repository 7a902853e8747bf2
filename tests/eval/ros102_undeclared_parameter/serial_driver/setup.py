from setuptools import setup

setup(
    name='serial_driver',
    version='0.1.0',
    packages=['serial_driver'],
    data_files=[('share/serial_driver', ['package.xml'])],
    entry_points={'console_scripts': [
        'gait = serial_driver.gait:main',
        'driver = serial_driver.driver:main',
        'passthrough = serial_driver.passthrough:main',
    ]},
)
