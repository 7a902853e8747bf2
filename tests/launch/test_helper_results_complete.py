"""A helper's result is complete when its caller first uses it.

A mission bring-up includes one manager's launch file per adaptation mode, each path built by a
small helper (``_launch_file(pkg, name)``). If the caller ran before the helper, it passed a
half-known path to ``os.path.join`` and the library's unknown result stuck to the launch
description source for good: every include read "one of several launch files" and no manager
was launched. The engine runs a call it has never analysed before the caller reads its result
(:meth:`flake8_rosgraph.absint.engine.Analysis.run_now`), so each include names its own file.
"""
from __future__ import annotations

from pathlib import Path

from flake8_rosgraph.analysis import build_graph
from flake8_rosgraph.launch.api import judged_graph
from flake8_rosgraph.rules import RuleConfig, run_rules

MANAGERS = ("none", "random", "bt")

PACKAGE_XML = """\
<package format="3"><name>{name}</name><version>0.0.0</version><description>d</description>
<maintainer email="dev@example.com">dev</maintainer><license>MIT</license>
<export><build_type>ament_python</build_type></export></package>
"""

MANAGER = """\
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Manager(Node):
    def __init__(self):
        super().__init__('{mode}_manager')
        self.rate = self.declare_parameter('check_rate', 2.0).value
        self.create_subscription(String, 'mission_status', self.on_status, 10)

    def on_status(self, msg):
        self.get_logger().info(msg.data)


def main():
    rclpy.init()
    rclpy.spin(Manager())
"""

MANAGER_LAUNCH = """\
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(package='mgr_{mode}', executable='manager', name='{mode}_manager',
                                   parameters=[{{'check_rate': 5.0}}])])
"""

MISSION = """\
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.conditions import LaunchConfigurationEquals
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import Node


def _launch_file(package_name, filename):
    return os.path.join(get_package_share_directory(package_name), 'launch', filename)


def generate_launch_description():
    reporter = Node(package='mission', executable='reporter', name='mission_reporter')
    managers = [
{includes}    ]
    return LaunchDescription([reporter, *managers])
"""
INCLUDE = """\
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(_launch_file('mgr_{mode}', 'mgr_{mode}.launch.py')),
            condition=LaunchConfigurationEquals('manager', '{mode}')),
"""

REPORTER = """\
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Reporter(Node):
    def __init__(self):
        super().__init__('mission_reporter')
        self.status = self.create_publisher(String, 'mission_status', 10)


def main():
    rclpy.init()
    rclpy.spin(Reporter())
"""


def _workspace(root: Path) -> Path:
    files = {
        "mission/package.xml": PACKAGE_XML.format(name="mission"),
        "mission/setup.py": "from setuptools import setup\nsetup(name='mission', packages=['mission'], "
                            "entry_points={'console_scripts': ['reporter = mission.reporter:main']})\n",
        "mission/mission/__init__.py": "",
        "mission/mission/reporter.py": REPORTER,
        "mission/launch/mission.launch.py": MISSION.format(
            includes="".join(INCLUDE.format(mode=mode) for mode in MANAGERS)),
    }
    for mode in MANAGERS:
        pkg = f"mgr_{mode}"
        files.update({
            f"{pkg}/package.xml": PACKAGE_XML.format(name=pkg),
            f"{pkg}/setup.py": f"from setuptools import setup\nsetup(name='{pkg}', packages=['{pkg}'], "
                               f"entry_points={{'console_scripts': ['manager = {pkg}.manager:main']}})\n",
            f"{pkg}/{pkg}/__init__.py": "",
            f"{pkg}/{pkg}/manager.py": MANAGER.format(mode=mode),
            f"{pkg}/launch/{pkg}.launch.py": MANAGER_LAUNCH.format(mode=mode),
        })
    for rel, text in files.items():
        (root / rel).parent.mkdir(parents=True, exist_ok=True)
        (root / rel).write_text(text)
    return root


def test_each_include_names_its_own_launch_file(tmp_path: Path) -> None:
    root = _workspace(tmp_path / "ws")
    graph = build_graph(root)
    mission = next(s for s in graph.systems if s.launch_file == "mission/launch/mission.launch.py")
    assert mission.complete and not mission.problems
    assert sorted(n.name for n in mission.nodes) == ["bt_manager", "mission_reporter", "none_manager",
                                                     "random_manager"]  # each once, nothing else
    findings = run_rules(judged_graph(graph, graph.systems), RuleConfig())
    assert findings == []
