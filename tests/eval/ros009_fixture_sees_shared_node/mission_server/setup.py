from setuptools import setup

setup(
    name='mission_server',
    version='0.1.0',
    packages=['mission_server'],
    entry_points={'console_scripts': ['mission_server = mission_server.server:main']},
)
