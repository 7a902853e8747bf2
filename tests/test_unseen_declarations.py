"""A parameter declared by code the analysis cannot tie to its node: a science rig loads its
bus plugins by name (``importlib.import_module('rig.plugins.' + name)``) and hands them the
node; the CAN plugin declares ``can_bus`` on it. The launch file sets ``can_bus`` for the
node, which the graph shows declaring only ``rate``: the name is written at a declaration
the analysis did not attribute to a known node, so it is not reported as unknown (ROS204).
The unknown stays local to that one name: the launch file's misspelt ``rtae`` is reported."""
from __future__ import annotations

from pathlib import Path

from test_recall_globals_and_escapes import package
from test_workspace_discovery import write

from flake8_rosgraph.cache import build_report
from flake8_rosgraph.options import Settings

RIG = """
    import importlib
    import sys

    import rclpy
    from rclpy.node import Node


    def main():
        rclpy.init()
        node = Node('sample_arm')
        node.declare_parameter('rate', 10.0)
        plugins = [importlib.import_module('rig.plugins.' + name).Plugin(node) for name in sys.argv[1:]]
        rclpy.spin(node)
        for plugin in plugins:
            plugin.close()
"""
CAN = """
    from rcl_interfaces.msg import ParameterDescriptor
    from rclpy.node import Node


    class Plugin:
        '''The CAN bus the arm's motors hang on.'''

        def __init__(self, node: Node):
            self.bus = node.declare_parameter(
                'can_bus', 'can1', ParameterDescriptor(description='CAN interface')).value

        def close(self):
            pass
"""
LAUNCH = """
    from launch import LaunchDescription
    from launch_ros.actions import Node


    def generate_launch_description():
        return LaunchDescription([
            Node(package='rig', executable='arm', name='sample_arm',
                 parameters=[{'can_bus': 'can0', 'rtae': 20.0}]),
        ])
"""


def _unknown_parameters(tmp_path: Path, can: str = CAN) -> list[str]:
    files = package("rig", "'arm = rig.arm:main'", {"arm": RIG})
    files["rig/rig/plugins/__init__.py"] = ""
    files["rig/rig/plugins/can.py"] = can
    files["rig/launch/arm.launch.py"] = LAUNCH
    report = build_report(write(tmp_path, files), Settings())
    return sorted(f.message.split("'")[1] for f in report.findings if f.code == "ROS204")


def test_a_name_declared_by_a_plugin_the_analysis_cannot_tie_to_the_node_is_not_unknown(
        tmp_path: Path) -> None:
    assert _unknown_parameters(tmp_path) == ["rtae"]


def test_a_name_no_declaration_writes_is_still_unknown(tmp_path: Path) -> None:
    """The twin: the plugin declares another name; ``can_bus`` is declared nowhere."""
    assert _unknown_parameters(tmp_path, CAN.replace("'can_bus'", "'can_port'")) == ["can_bus", "rtae"]
