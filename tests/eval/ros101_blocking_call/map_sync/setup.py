from setuptools import setup

setup(
    name='map_sync',
    version='0.1.0',
    packages=['map_sync'],
    data_files=[('share/map_sync', ['package.xml'])],
    entry_points={'console_scripts': [
        'sync_node = map_sync.sync_node:main',
        'async_sync_node = map_sync.async_sync_node:main',
        'grouped_sync_node = map_sync.grouped_sync_node:main',
        'spinning_node = map_sync.spinning_node:main',
    ]},
)
