"""The engine's shortcuts change no result, byte for byte.

Each shortcut stands for a plain computation it must equal: values keep their text once
rendered, constants are shared, the argument texts of a model call are unparsed once per
call site, a branch test without calls or assignments is evaluated once per block visit
(not again on each edge), and the effect list and the call graph's task orders are kept
until the analysis changes. The graph JSON (launch systems included) and every finding and
diagnostic of realistic workspaces must be the same bytes with the shortcuts as with the
plain computations put back in their place.
"""
from __future__ import annotations

import ast
import json
import textwrap
from pathlib import Path

import pytest

from flake8_rosgraph.absint import values
from flake8_rosgraph.absint.callgraph import CallGraph
from flake8_rosgraph.absint.calls import CallSemantics
from flake8_rosgraph.absint.engine import Analysis
from flake8_rosgraph.absint.interpreter import Interpreter
from flake8_rosgraph.absint.values import Value
from flake8_rosgraph.analysis import build_graph
from flake8_rosgraph.cache import build_report
from flake8_rosgraph.launch.api import graph_to_json_obj, system_to_json
from flake8_rosgraph.options import Settings

REPO = Path(__file__).resolve().parents[2]

#: Two packages: a node base class in one module, nodes in another that branch on parameters
#: (pure tests), on calls and on an assignment expression (tests evaluated on each edge), and
#: on a library call that stores what the test reads next; a launch file starting them.
BRANCHING = {
    "src/fleet_base/package.xml": "<package format='3'><name>fleet_base</name></package>\n",
    "src/fleet_base/setup.py": "from setuptools import setup\nsetup(name='fleet_base', packages=['fleet_base'])\n",
    "src/fleet_base/fleet_base/__init__.py": "",
    "src/fleet_base/fleet_base/node.py": """\
        from rclpy.node import Node
        from std_msgs.msg import String

        PREFIX = 'fleet'


        class FleetNode(Node):
            def __init__(self, name, simulated=False):
                super().__init__(name)
                self.simulated = simulated
                self.declare_parameter('rate', 10.0)
                if self.simulated and PREFIX:
                    self.status = self.create_publisher(String, PREFIX + '/sim_status', 10)
                elif not self.simulated:
                    self.status = self.create_publisher(String, PREFIX + '/status', 10)
                else:
                    self.status = None

            def topic(self, leaf):
                return f'{PREFIX}/{self.get_name()}/{leaf}' if leaf else PREFIX
        """,
    "src/fleet_apps/package.xml": "<package format='3'><name>fleet_apps</name>"
                                  "<exec_depend>fleet_base</exec_depend></package>\n",
    "src/fleet_apps/setup.py": """\
        from setuptools import setup
        setup(name='fleet_apps', packages=['fleet_apps'],
              entry_points={'console_scripts': ['drivers = fleet_apps.drivers:main']})
        """,
    "src/fleet_apps/fleet_apps/__init__.py": "",
    "src/fleet_apps/fleet_apps/drivers.py": """\
        import rclpy
        from fleet_base.node import FleetNode
        from std_msgs.msg import String

        SENSORS = ['lidar', 'sonar', 'camera']


        class Driver(FleetNode):
            def __init__(self, sensor, index):
                super().__init__(f'driver_{sensor}', simulated=index > 1)
                self.sensor = sensor
                if (leaf := self.leaf_for(sensor)) is not None:
                    self.pub = self.create_publisher(String, self.topic(leaf), 10)
                if self.get_parameter('rate').value > 5.0 and sensor != 'camera':
                    self.timer = self.create_timer(0.1, self.tick)
                while not self.has_parameter('gain'):
                    self.declare_parameter('gain', 1.0)
                if self.declare_parameter('mode', 'raw').value == 'raw':
                    self.create_subscription(String, self.topic('cmd'), self.on_cmd, 10)

            def leaf_for(self, sensor):
                return None if sensor == 'camera' else sensor + '/data'

            def tick(self):
                if self.pub is not None and self.sensor:
                    self.pub.publish(String(data=self.sensor))

            def on_cmd(self, msg):
                if msg.data == 'stop' or not msg.data:
                    self.destroy_timer(self.timer)


        def main():
            rclpy.init()
            nodes = [Driver(sensor, i) for i, sensor in enumerate(SENSORS)]
            for node in nodes:
                rclpy.spin_once(node)
        """,
    "src/fleet_apps/launch/fleet.launch.py": """\
        from launch import LaunchDescription
        from launch_ros.actions import Node


        def generate_launch_description():
            return LaunchDescription([
                Node(package='fleet_apps', executable='drivers', name='drivers',
                     remappings=[('fleet/driver_lidar/cmd', 'fleet/cmd')]),
            ])
        """,
}


def _outputs(root: Path) -> str:
    """Everything the analysis reports on ``root``: graph JSON with systems, findings, diagnostics."""
    graph = build_graph(root)
    obj = graph_to_json_obj(graph)
    obj["systems"] = [system_to_json(s) for s in graph.systems]
    report = build_report(root, Settings.resolve({}, {}))
    return json.dumps([obj, [repr(f) for f in report.findings], [repr(d) for d in report.diagnostics]],
                      indent=1, sort_keys=True)


def _without_shortcuts(monkeypatch: pytest.MonkeyPatch) -> None:
    """Put the plain computation back in place of each shortcut."""
    monkeypatch.setattr(Value, "__repr__", Value._render)
    monkeypatch.setattr(values, "_MAX_SHARED_CONSTS", 0)
    monkeypatch.setattr(values, "_CONSTS", {})
    monkeypatch.setattr(CallSemantics, "_argument_texts_at",
                        lambda self, model, receiver, node: self.argument_texts(model, receiver, node))
    monkeypatch.setattr(Interpreter, "_pure_test", lambda self, test: False)
    all_effects = Analysis.all_effects

    def every_time(self: Analysis) -> list:
        self._all_effects = None
        return all_effects(self)
    monkeypatch.setattr(Analysis, "all_effects", every_time)
    monkeypatch.setattr(CallGraph, "tasks", lambda self: iter(sorted(self._calls, key=repr)))
    monkeypatch.setattr(CallGraph, "tasks_of", lambda self, fid: sorted(
        (t for t in self._calls if t[0] == "fn" and t[1] == fid), key=repr))


@pytest.fixture
def branching(tmp_path: Path) -> Path:
    root = tmp_path / "ws"
    for rel, text in BRANCHING.items():
        path = root / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(textwrap.dedent(text), encoding="utf-8")
    return root


@pytest.mark.parametrize("where", ["examples", "tests/readme_workspace", "branching"])
def test_shortcuts_give_the_plain_computations_results(where: str, branching: Path,
                                                       monkeypatch: pytest.MonkeyPatch) -> None:
    root = branching if where == "branching" else REPO / where
    with_shortcuts = _outputs(root)
    assert '"nodes": []' not in with_shortcuts, "the workspace has nodes to compare"
    _without_shortcuts(monkeypatch)
    assert _outputs(root) == with_shortcuts


def test_branching_workspace_takes_both_kinds_of_test(branching: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The workspace above reaches both paths: tests whose value is reused on the edges and
    tests evaluated again on each edge (a call, an assignment expression)."""
    answers: dict[str, bool] = {}
    pure_test = Interpreter._pure_test

    def recorded(self: Interpreter, test) -> bool:
        answers[ast.unparse(test)] = pure_test(self, test)
        return answers[ast.unparse(test)]
    monkeypatch.setattr(Interpreter, "_pure_test", recorded)
    graph = build_graph(branching)
    assert answers["self.simulated"] and answers["PREFIX"] and answers["self.pub is not None"]
    assert answers["msg.data == 'stop'"] and answers["msg.data"]
    assert not answers["(leaf := self.leaf_for(sensor)) is not None"]
    assert not answers["self.declare_parameter('mode', 'raw').value == 'raw'"]
    assert not answers["self.has_parameter('gain')"]
    assert {"/driver_lidar", "/driver_sonar", "/driver_camera"} <= {n.fqn for n in graph.nodes}
