from setuptools import setup

package_name = 'chatter_demo'

setup(
    name=package_name,
    version='0.1.0',
    packages=[package_name],
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    entry_points={
        'console_scripts': [
            'talker = chatter_demo.talker:main',
            'listener = chatter_demo.listener:main',
            'recorder = chatter_demo.recorder:main',
            'logger = chatter_demo.logger:main',
            'relay = chatter_demo.relay:main',
        ],
    },
)
