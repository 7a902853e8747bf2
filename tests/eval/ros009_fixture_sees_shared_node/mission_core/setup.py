from setuptools import setup

setup(name='mission_core', version='0.1.0', packages=['mission_core'])
