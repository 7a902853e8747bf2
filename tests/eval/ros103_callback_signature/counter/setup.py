from setuptools import setup

setup(
    name='counter',
    version='0.1.0',
    packages=['counter'],
    data_files=[('share/counter', ['package.xml'])],
    entry_points={'console_scripts': ['counter = counter.node:main']},
)
