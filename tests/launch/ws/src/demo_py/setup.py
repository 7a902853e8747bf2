from setuptools import setup

package_name = 'demo_py'

setup(
    name=package_name,
    version='0.0.1',
    packages=[package_name],
    entry_points={
        'console_scripts': [
            'talker = ' + package_name + '.talker:main',
            f'listener = {package_name}.listener:main',
            'monitor = demo_py.monitor:main',
        ],
    },
)
