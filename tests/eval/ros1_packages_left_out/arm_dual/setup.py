from setuptools import setup

setup(
    name='arm_dual',
    version='0.3.0',
    packages=['arm_dual'],
    data_files=[('share/arm_dual', ['package.xml'])],
    entry_points={'console_scripts': ['markers = arm_dual.markers:main']},
)
