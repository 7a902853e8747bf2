from setuptools import setup

setup(name='nav_bridge', packages=['nav_bridge'],
      entry_points={'console_scripts': ['odom_relay = nav_bridge.odom_relay:main']})
