"""ROS205: a parameter file section that no node started with the file matches (as rcl matches node keys).

The workspace: a Python package of two nodes (a driver that declares its rate, a
monitor), a bring-up package whose launch files start them in a namespace or at
the root, and parameter files whose sections match or miss them.
"""
from __future__ import annotations

import textwrap
from pathlib import Path

from flake8_rosgraph.analysis import build_graph
from flake8_rosgraph.launch.api import judged_graph
from flake8_rosgraph.rules import RuleConfig, run_rules

DRIVER = '''\
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import LaserScan


class LidarDriver(Node):
    def __init__(self):
        super().__init__('lidar_driver')
        rate = self.declare_parameter('rate', 10.0).value
        self.frame = self.declare_parameter('frame_id', 'laser').value
        self.pub = self.create_publisher(LaserScan, 'scan', 10)
        self.timer = self.create_timer(1.0 / rate, self.tick)

    def tick(self):
        self.pub.publish(LaserScan())


def main():
    rclpy.init()
    rclpy.spin(LidarDriver())
'''

MONITOR = '''\
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import LaserScan


class ScanMonitor(Node):
    def __init__(self):
        super().__init__('scan_monitor')
        self.declare_parameter('timeout', 1.0)
        self.create_subscription(LaserScan, 'scan', self.on_scan, 10)

    def on_scan(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(ScanMonitor())
'''

SETUP = '''\
from setuptools import setup

setup(
    name='lidar_driver',
    packages=['lidar_driver'],
    entry_points={'console_scripts': [
        'driver = lidar_driver.driver:main',
        'monitor = lidar_driver.monitor:main',
    ]},
)
'''

LAUNCH = '''\
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    params = PathJoinSubstitution([FindPackageShare('robot_bringup'), 'config', '{config}'])
    return LaunchDescription([
        Node(package='lidar_driver', executable='driver', namespace='{namespace}', parameters=[params]),
        Node(package='lidar_driver', executable='monitor', namespace='{namespace}', parameters=[params]),
    ])
'''


def workspace(root: Path, configs: dict[str, str], launches: dict[str, tuple[str, str]]) -> Path:
    files = {
        "src/lidar_driver/package.xml": "<package format='3'><name>lidar_driver</name></package>\n",
        "src/lidar_driver/setup.py": SETUP,
        "src/lidar_driver/lidar_driver/__init__.py": "",
        "src/lidar_driver/lidar_driver/driver.py": DRIVER,
        "src/lidar_driver/lidar_driver/monitor.py": MONITOR,
        "src/robot_bringup/package.xml": "<package format='3'><name>robot_bringup</name></package>\n",
        "src/robot_bringup/setup.py": "from setuptools import setup\nsetup(name='robot_bringup')\n",
    }
    files.update({f"src/robot_bringup/config/{name}": textwrap.dedent(text) for name, text in configs.items()})
    for name, (config, namespace) in launches.items():
        files[f"src/robot_bringup/launch/{name}"] = LAUNCH.format(config=config, namespace=namespace)
    for rel, text in files.items():
        (root / rel).parent.mkdir(parents=True, exist_ok=True)
        (root / rel).write_text(text)
    return root


def ros205(root: Path) -> list[tuple[str, int, str]]:
    graph = build_graph(root)
    findings = run_rules(judged_graph(graph, graph.systems), RuleConfig(), ["ROS205"])
    return [(f.location.path, f.location.line, f.message) for f in findings]


CONFIG = "src/robot_bringup/config/lidar.yaml"


def test_a_section_for_the_node_outside_its_namespace_is_ignored(tmp_path):
    root = workspace(tmp_path, {"lidar.yaml": """\
        lidar_driver:
          ros__parameters:
            rate: 20.0
        /front/scan_monitor:
          ros__parameters:
            timeout: 0.5
        """}, {"lidar.launch.py": ("lidar.yaml", "front")})
    (finding,) = ros205(root)
    assert finding[:2] == (CONFIG, 1)
    assert "'/lidar_driver' matches no node" in finding[2]
    assert "did you mean '/front/lidar_driver'?" in finding[2]


def test_matching_sections_wildcards_and_nested_namespaces_stay_quiet(tmp_path):
    root = workspace(tmp_path, {"lidar.yaml": """\
        /**:
          ros__parameters:
            use_sim_time: false
        /*/lidar_driver:
          ros__parameters:
            rate: 20.0
        front:
          scan_monitor:
            ros__parameters:
              timeout: 0.5
        """}, {"lidar.launch.py": ("lidar.yaml", "front")})
    assert ros205(root) == []


def test_a_misspelt_node_key_at_the_root(tmp_path):
    root = workspace(tmp_path, {"lidar.yaml": """\
        lidar_drvier:
          ros__parameters:
            rate: 20.0
        scan_monitor:
          ros__parameters:
            timeout: 0.5
        """}, {"lidar.launch.py": ("lidar.yaml", "/")})
    (finding,) = ros205(root)
    assert finding[1] == 1 and "did you mean '/lidar_driver'?" in finding[2]


def test_a_file_shared_by_two_launch_files_is_judged_over_both(tmp_path):
    root = workspace(tmp_path, {"lidar.yaml": """\
        /front/lidar_driver:
          ros__parameters:
            rate: 20.0
        /rear/lidar_driver:
          ros__parameters:
            rate: 15.0
        """}, {"front.launch.py": ("lidar.yaml", "front"), "rear.launch.py": ("lidar.yaml", "rear")})
    assert ros205(root) == []


def test_a_namespace_from_an_argument_without_value_is_not_judged(tmp_path):
    root = workspace(tmp_path, {"lidar.yaml": """\
        lidar_driver:
          ros__parameters:
            rate: 20.0
        """}, {})
    launch = root / "src/robot_bringup/launch/lidar.launch.py"
    launch.parent.mkdir(parents=True, exist_ok=True)
    launch.write_text(LAUNCH.format(config="lidar.yaml", namespace="X")
                      .replace("namespace='X'", "namespace=LaunchConfiguration('robot')")
                      .replace("from launch.substitutions import PathJoinSubstitution",
                               "from launch.substitutions import LaunchConfiguration, PathJoinSubstitution"))
    assert ros205(root) == []
