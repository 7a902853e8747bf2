"""ROS202 on private names: a remap of ``~/x`` is judged like any other, the per-node built-ins are not."""
from __future__ import annotations

from pathlib import Path

from flake8_rosgraph.analysis import build_graph
from flake8_rosgraph.launch.api import judged_graph
from flake8_rosgraph.rules import RuleConfig, run_rules

NODE = '''\
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Driver(Node):
    def __init__(self):
        super().__init__('driver')
        self.status = self.create_publisher(String, '~/status', 10)
        self.create_subscription(String, 'command', self.on_command, 10)

    def on_command(self, msg):
        self.status.publish(msg)


def main():
    rclpy.init()
    rclpy.spin(Driver())
'''

LAUNCH = '''\
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='driver_pkg', executable='driver', namespace='arm',
             remappings=[{remaps}]),
    ])
'''


def ros202(tmp_path: Path, remaps: str) -> list[tuple[int, str]]:
    files = {
        "src/driver_pkg/package.xml": "<package format='3'><name>driver_pkg</name></package>\n",
        "src/driver_pkg/setup.py": ("from setuptools import setup\nsetup(name='driver_pkg', packages=['driver_pkg'],\n"
                                    "      entry_points={'console_scripts': ['driver = driver_pkg.driver:main']})\n"),
        "src/driver_pkg/driver_pkg/__init__.py": "",
        "src/driver_pkg/driver_pkg/driver.py": NODE,
        "src/driver_pkg/launch/arm.launch.py": LAUNCH.format(remaps=remaps),
    }
    for rel, text in files.items():
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / rel).write_text(text)
    graph = build_graph(tmp_path)
    return [(f.location.line, f.message) for f in run_rules(judged_graph(graph, graph.systems), RuleConfig(),
                                                             ["ROS202"])]


def test_a_typo_in_a_private_remap_is_reported_with_the_name_meant(tmp_path):
    (finding,) = ros202(tmp_path, "('~/stauts', '/arm_status')")
    assert finding[0] == 7  # the line of the Node action that holds the remapping
    assert "remap '~/stauts' -> '/arm_status' matches no name node '/arm/driver' uses" in finding[1]
    assert "did you mean '/arm/driver/status'?" in finding[1]


def test_private_remaps_that_match_and_built_in_services_stay_quiet(tmp_path):
    assert ros202(tmp_path, "('~/status', '/arm_status'), ('~/get_parameters', '/arm_params')") == []
