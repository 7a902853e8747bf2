from setuptools import setup

setup(name='demo_bringup', version='0.0.1', packages=[])
