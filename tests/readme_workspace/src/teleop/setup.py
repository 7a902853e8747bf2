from setuptools import setup

setup(name='teleop', packages=['teleop'],
      entry_points={'console_scripts': ['keys = teleop.keys:main']})
