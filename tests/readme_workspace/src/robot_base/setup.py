from setuptools import setup

setup(name='robot_base', packages=['robot_base'],
      entry_points={'console_scripts': ['base_driver = robot_base.base_driver:main']})
