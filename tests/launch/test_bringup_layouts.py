"""Bringup layouts seen in real multi-robot packages.

* A ROS package whose ``launch/`` folder holds an ``__init__.py``: the folder is
  named like the ``launch`` library but is not installed as Python, so
  ``from launch import LaunchDescription`` is the library's — the launch files
  must still be followed, and its nodes launched in their namespaces.
* A launch file included by another with arguments: its placeholder defaults
  (``LaunchConfiguration('sensor', default='sensor_default')``) are not judged
  alone; what the includer passes is.
"""
from __future__ import annotations

from pathlib import Path

from flake8_rosgraph.analysis import build_graph
from flake8_rosgraph.launch.api import judged_graph
from flake8_rosgraph.rules import RuleConfig, run_rules

LAYER = '''\
import rclpy
from rclpy.node import Node
from std_msgs.msg import Float32


class {cls}(Node):
    def __init__(self):
        super().__init__('{name}')
        self.create_subscription(Float32, self.get_namespace() + '/raw', self.on_raw, 10)
        self.pub = self.create_publisher(Float32, self.get_namespace() + '/range_data', 10)

    def on_raw(self, msg):
        self.pub.publish(msg)


def main():
    rclpy.init()
    rclpy.spin({cls}())
'''

PATTERN = '''\
import launch_ros.actions
from launch import LaunchDescription
from launch.substitutions import LaunchConfiguration


def generate_launch_description():
    robot = LaunchConfiguration('robot_namespace', default='robot_namespace_default')
    sensor = LaunchConfiguration('sensor_type', default='sensor_type_default')
    ld = LaunchDescription()
    ld.add_action(launch_ros.actions.Node(package='swarm', executable=[sensor, '_layer'], namespace=robot))
    ld.add_action(launch_ros.actions.Node(package='swarm', executable='{watchdog}', namespace=robot))
    return ld
'''

ROBOT = '''\
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource


def generate_launch_description():
    launch_dir = os.path.join(get_package_share_directory('swarm'), 'launch')
    return LaunchDescription([
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(os.path.join(launch_dir, 'pattern.launch.py')),
            launch_arguments={'robot_namespace': 'robot_1', 'sensor_type': '{sensor}'}.items()),
    ])
'''

SETUP = '''\
from setuptools import setup

setup(name='swarm', packages=['swarm'], entry_points={'console_scripts': [
    'lidar_layer = swarm.lidar_layer:main',
    'sonar_layer = swarm.sonar_layer:main',
    'watchdog = swarm.lidar_layer:main',
]})
'''


def swarm_findings(tmp_path: Path, sensor: str = "lidar", watchdog: str = "watchdog") -> list[tuple[str, str]]:
    files = {
        "src/swarm/package.xml": "<package format='3'><name>swarm</name></package>\n",
        "src/swarm/setup.py": SETUP,
        "src/swarm/swarm/__init__.py": "",
        "src/swarm/swarm/lidar_layer.py": LAYER.format(cls="LidarLayer", name="lidar_layer"),
        "src/swarm/swarm/sonar_layer.py": LAYER.format(cls="SonarLayer", name="sonar_layer"),
        "src/swarm/launch/__init__.py": "",
        "src/swarm/launch/pattern.launch.py": PATTERN.replace("{watchdog}", watchdog),
        "src/swarm/launch/robot.launch.py": ROBOT.replace("{sensor}", sensor),
    }
    for rel, text in files.items():
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / rel).write_text(text)
    graph = build_graph(tmp_path)
    launched = {(s.launch_file, n.executable, n.namespace) for s in graph.systems for n in s.nodes}
    assert ("src/swarm/launch/robot.launch.py", "lidar_layer" if sensor == "lidar" else f"{sensor}_layer",
            "/robot_1") in launched, launched
    return sorted((f.code, f.location.path) for f in run_rules(judged_graph(graph, graph.systems), RuleConfig(),
                                                                 ["ROS006", "ROS201"]))


def test_launch_folder_named_like_the_library_is_followed_and_defaults_are_not_judged_alone(tmp_path):
    # the layers are launched in /robot_1: their namespace-built names are fine; the pattern's
    # 'sensor_type_default_layer' is a placeholder the includer replaces
    assert swarm_findings(tmp_path) == []


def test_what_the_includer_passes_is_judged(tmp_path):
    assert swarm_findings(tmp_path, sensor="lidr") == [("ROS201", "src/swarm/launch/pattern.launch.py")]


def test_a_literal_executable_in_an_included_file_is_still_judged(tmp_path):
    assert swarm_findings(tmp_path, watchdog="watchdgo") == [("ROS201", "src/swarm/launch/pattern.launch.py")]
