from setuptools import setup

package_name = 'thesis_graph'

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
            'node_1 = thesis_graph.first_pair:main_node_1',
            'node_2 = thesis_graph.first_pair:main_node_2',
            'node_3 = thesis_graph.second_pair:main_node_3',
            'node_4 = thesis_graph.second_pair:main_node_4',
        ],
    },
)
