from setuptools import find_packages, setup

package_name = 'thesis_graph'

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages',
         ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='flake8-rosgraph maintainers',
    maintainer_email='maintainers@flake8-rosgraph.invalid',
    description='The four-node / eight-topic graph of the LiSA thesis.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'thesis_graph = thesis_graph.main:main',
        ],
    },
)
