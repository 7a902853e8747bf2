from setuptools import setup

setup(
    name='heartbeat',
    version='0.1.0',
    packages=['heartbeat'],
    data_files=[('share/heartbeat', ['package.xml'])],
    entry_points={'console_scripts': ['heartbeat = heartbeat.node:main']},
)
