from setuptools import setup

setup(
    name='talker',
    version='0.1.0',
    packages=['talker'],
    data_files=[('share/talker', ['package.xml'])],
    entry_points={'console_scripts': [
        'talker = talker.main:main',
        'restart = talker.main:restart',
        'ordered = talker.main:ordered',
    ]},
)
