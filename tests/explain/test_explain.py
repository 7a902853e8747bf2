"""``graph --explain``: every creation site missing from the graph, or known only partly, with
the reasons the analysis recorded.

The workspaces are written as files; each creation call carries its expected verdict as a
trailing comment — ``# ok`` (in the graph, fully known), ``# unknown: <words>`` or
``# missing: <words>`` (``<words>`` must appear in the reasons) — and every call of a
creation method or class must carry one, so a site the report forgets fails as surely as a
wrong reason.
"""
from __future__ import annotations

import re
import subprocess
import sys
import textwrap
from pathlib import Path

from flake8_rosgraph.analysis import analyse
from flake8_rosgraph.explain import explain
from test_workspace_discovery import write

EXPECT = re.compile(r"#\s*(ok|unknown|missing)\b:?\s*(.*)$")

PACKAGE_XML = """<?xml version="1.0"?>
<package format="3"><name>{name}</name><version>0.1.0</version>
<description>d</description><maintainer email="a@b.c">a</maintainer><license>MIT</license>
<exec_depend>rclpy</exec_depend><export><build_type>ament_python</build_type></export></package>
"""


def expectations(root: Path) -> dict[tuple[str, int], tuple[str, str]]:
    out = {}
    for path in sorted(root.rglob("*.py")):
        for number, line in enumerate(path.read_text().splitlines(), 1):
            match = EXPECT.search(line)
            if match:
                out[(path.relative_to(root).as_posix(), number)] = (match.group(1),
                                                                     match.group(2).strip())
    return out


def check(root: Path) -> None:
    graph, analysis = analyse(root)
    report = explain(analysis, graph)
    got = {(e.site.path, e.site.line): e for e in report.explanations}
    wanted = expectations(root)
    assert sorted(got) == sorted(wanted), "sites found differ from the annotated ones"
    for where, (status, words) in wanted.items():
        item = got[where]
        want = "complete" if status == "ok" else status
        assert item.status == want, (where, item)
        assert words in " ".join(item.reasons), (where, item.reasons)


FLEET = {
    "fleet/package.xml": PACKAGE_XML.format(name="fleet"),
    "fleet/setup.py": """
        from setuptools import setup
        setup(name='fleet', packages=['fleet'],
              entry_points={'console_scripts': ['driver = fleet.driver:main']})
    """,
    "fleet/fleet/__init__.py": "",
    "fleet/fleet/base.py": """
        from rclpy.node import Node
        from std_msgs.msg import String


        class BaseDriver(Node):
            def __init__(self, name, namespace):
                super().__init__(name, namespace=namespace)  # ok
                self.status = self.create_publisher(String, 'status', 10)  # ok
                for topic in self.get_parameter('extra_topics').value:
                    self.create_publisher(String, topic, 10)  # unknown: loop variable `topic`
                self.create_timer(0.5, self.tick)  # ok

            def tick(self):
                pass

            def shutdown_hook(self):
                raise NotImplementedError('subclasses define it')
                self.create_publisher(String, 'bye', 1)  # missing: never reaches this line

            def debug_topics(self):
                # public: whoever holds a driver may call it (analysed with unknown arguments)
                self.create_publisher(String, 'debug', 1)  # ok

            def _trace_topics(self):
                self.create_publisher(String, 'trace', 1)  # missing: method BaseDriver._trace_topics is never called
    """,
    "fleet/fleet/driver.py": """
        import rclpy
        from std_srvs.srv import Trigger

        from fleet.base import BaseDriver
        from .calibration import Calibrator


        class Driver(BaseDriver):
            def __init__(self):
                super().__init__('driver', '/robot1')
                self.srv = self.create_service(Trigger, 'reset', self.on_reset)  # ok
                self.cli = self.create_client(Trigger, self.get_parameter('peer').value)  # unknown: ROS parameter


            def on_reset(self, request, response):
                self.shutdown_hook()
                return response


        class Spare(BaseDriver):
            def __init__(self):
                super().__init__('spare', '/robot2')
                self.create_client(Trigger, 'spare_reset')  # ok


        def attach(node):
            node.create_subscription(Trigger, 'never', print, 10)  # missing: parameter `node`


        def main():
            rclpy.init()
            driver = Driver()
            rclpy.spin(driver)
    """,
    "fleet/fleet/helpers.py": """
        from rclpy.qos import qos_profile_sensor_data
        from std_msgs.msg import String
        from .does_not_exist import topic_table


        class Recorder:
            def start(self, node):
                node.create_subscription(String, 'log', self.on_log, 10)  # missing: class Recorder is never instantiated

            def on_log(self, msg):
                pass
    """,
    "fleet/fleet/pure.py": """
        def make_timer(node):
            return node.create_timer(1.0, print)  # missing: imports no modelled library
    """,
    "fleet/fleet/calibration.py": """
        class Calibrator:
            pass
    """,
}


def test_reasons_on_a_package(tmp_path: Path) -> None:
    check(write(tmp_path, FLEET))


def test_unresolved_workspace_import_is_named(tmp_path: Path) -> None:
    root = write(tmp_path, FLEET)
    graph, analysis = analyse(root)
    report = explain(analysis, graph)
    recorder = next(e for e in report.explanations if e.site.path.endswith("helpers.py"))
    assert "imports not resolved in the workspace: .does_not_exist" in recorder.reasons


def test_launch_node_of_launch_ros_is_not_a_site(tmp_path: Path) -> None:
    """``Node`` of launch_ros is not rclpy's: names are resolved through imports."""
    root = write(tmp_path, {
        "demo/package.xml": PACKAGE_XML.format(name="demo"),
        "demo/launch/demo.launch.py": """
            from launch import LaunchDescription
            from launch_ros.actions import Node


            def generate_launch_description():
                return LaunchDescription([Node(package='demo', executable='talker')])
        """,
        "demo/demo/talker.py": """
            import rclpy
            from rclpy.node import Node as RosNode


            def main():
                rclpy.init()
                node = rclpy.create_node('talker')  # ok
                other = RosNode('other', namespace=None)  # ok
                rclpy.spin(node)
        """,
    })
    check(root)


def test_cli_prints_gaps_and_count(tmp_path: Path) -> None:
    root = write(tmp_path, FLEET)
    run = subprocess.run([sys.executable, "-m", "flake8_rosgraph", "graph", str(root),
                          "--explain", "--verbose"], capture_output=True, text=True, check=True)
    lines = run.stderr.splitlines()
    assert any(line.startswith("fleet/fleet/helpers.py:8:9: node.create_subscription: not in the "
                               "graph: class Recorder is never instantiated") for line in lines)
    assert lines[-1].startswith("creation sites: 13, in the graph and fully known: 6 (46%), with unknowns: 2, not in the graph: 5")
    quiet = subprocess.run([sys.executable, "-m", "flake8_rosgraph", "graph", str(root)],
                           capture_output=True, text=True, check=True)
    assert "creation sites" not in quiet.stderr and "not in the graph" not in quiet.stderr


def test_launch_file_not_followed_is_said(tmp_path: Path) -> None:
    """``graph --launch`` names what it could not follow instead of printing a partial
    system silently; a fully followed file adds nothing."""
    root = write(tmp_path, dict(FLEET, **{
        "fleet/launch/dynamic.launch.py": """
            from launch import LaunchDescription
            from launch.actions import OpaqueFunction
            from launch_ros.actions import Node
            from fleet_tools.spawning import spawn  # not in the workspace


            def generate_launch_description():
                return LaunchDescription([OpaqueFunction(function=spawn)])
        """,
        "fleet/launch/plain.launch.py": """
            from launch import LaunchDescription
            from launch_ros.actions import Node


            def generate_launch_description():
                return LaunchDescription([Node(package='fleet', executable='driver')])
        """,
    }))
    base = [sys.executable, "-m", "flake8_rosgraph", "graph", str(root), "--launch"]
    run = subprocess.run(base + [str(root / "fleet/launch/dynamic.launch.py")],
                         capture_output=True, text=True, check=True)
    assert ("fleet/launch/dynamic.launch.py:8: warning: OpaqueFunction of a function the analysis cannot "
            "determine is not followed") in run.stderr
    assert "dynamic.launch.py is not fully followed: 1 construct(s) not followed" in run.stderr
    plain = subprocess.run(base + [str(root / "fleet/launch/plain.launch.py")],
                           capture_output=True, text=True, check=True)
    assert "not fully followed" not in plain.stderr and "not followed" not in plain.stderr


def test_reasons_for_unknown_namespace_type_and_built_names(tmp_path: Path) -> None:
    """A node namespace from an argument, the relative names it takes away, a type chosen
    by a module-level condition between two messages (one entity per type: known) or
    between a message and what an unmodelled call returns (unknown), and a name built from
    a run-time call."""
    check(write(tmp_path, {
        "tester/package.xml": PACKAGE_XML.format(name="tester"),
        "tester/tester/__init__.py": "",
        "tester/tester/tester.py": """
            import os
            import sys

            import rclpy
            from rclpy.node import Node

            if os.environ.get('ROS_DISTRO') == 'humble':
                from geometry_msgs.msg import Twist as CmdVel
            else:
                from geometry_msgs.msg import TwistStamped as CmdVel
            if os.environ.get('SIM'):
                from std_msgs.msg import Bool as Trigger
            else:
                from vendor_interfaces import load_trigger_type
                Trigger = load_trigger_type()
            from std_msgs.msg import String


            class Tester(Node):
                def __init__(self, namespace):
                    super().__init__('tester', namespace=namespace)  # unknown: parameter `namespace` of __init__
                    self.create_publisher(String, 'initialpose', 1)  # unknown: `initialpose` is relative to the namespace of its node
                    self.create_publisher(String, '/abs/goal', 1)  # ok


            class Driver(Node):
                def __init__(self):
                    super().__init__('driver_{}'.format(os.getpid()))  # unknown: built from `'driver_{}'.format(os.getpid())`
                    self.create_publisher(CmdVel, '/cmd_vel', 1)  # ok
                    self.create_publisher(Trigger, '/trigger', 1)  # unknown: `Trigger` is bound 2 times at module level


            def main():
                rclpy.init()
                rclpy.spin(Tester(sys.argv[1]))
                rclpy.spin(Driver())
        """,
    }))


def test_calls_of_the_workspaces_own_wrappers_are_not_sites(tmp_path: Path) -> None:
    """A plugin base class forwarding ``create_client`` to its node (mavros' ``PluginModule``):
    the site is the forwarding call inside the wrapper, not each plugin's call of the wrapper."""
    write(tmp_path, {
        "uav/package.xml": PACKAGE_XML.format(name="uav"),
        "uav/setup.py": """
            from setuptools import setup
            setup(name='uav', packages=['uav'],
                  entry_points={'console_scripts': ['uav = uav.client:main']})
        """,
        "uav/uav/__init__.py": "",
        "uav/uav/plugin.py": """
            from std_srvs.srv import Trigger


            class PluginModule:
                def __init__(self, node):
                    self._node = node

                def create_client(self, srv_type, name):
                    return self._node.create_client(srv_type, '/uav/' + name)  # ok

                def own_trigger(self):
                    return self.create_client(Trigger, 'reset')
        """,
        "uav/uav/client.py": """
            import rclpy
            from rclpy.node import Node
            from std_srvs.srv import SetBool, Trigger

            from uav.plugin import PluginModule


            class Arming(PluginModule):
                def arm(self):
                    return self.create_client(SetBool, 'arming')


            class Bare(Node):
                def __init__(self):
                    super().__init__('bare')  # ok
                    self.create_client(Trigger, 'land')  # ok


            def main():
                rclpy.init()
                node = rclpy.create_node('uav_client')  # ok
                Arming(node).arm()
                PluginModule(node).own_trigger()
                rclpy.spin(Bare())
        """,
    })
    check(tmp_path)


def test_a_site_whose_function_is_called_past_the_context_bound_is_not_complete(tmp_path: Path) -> None:
    """A helper called with more names than calls keep their arguments: the graph lists the
    first calls' topics, all known, but the further calls (analysed with unknown arguments,
    the node too) create what the graph lacks — not "complete". The same helper called a few
    times is complete."""
    many = "".join(f"    add_topic(node, 'cell_{i}/temperature')\n" for i in range(30))
    write(tmp_path, {
        "battery/package.xml": PACKAGE_XML.format(name="battery"),
        "battery/setup.py": """
            from setuptools import setup
            setup(name='battery', packages=['battery'],
                  entry_points={'console_scripts': ['cells = battery.cells:main',
                                                    'pack = battery.pack:main']})
        """,
        "battery/battery/__init__.py": "",
        "battery/battery/cells.py": textwrap.dedent("""
            import rclpy
            from rclpy.node import Node
            from sensor_msgs.msg import Temperature


            def add_topic(node, name):
                return node.create_publisher(Temperature, name, 10)  # unknown: called in more than 24 different ways


            def main():
                rclpy.init()
                node = Node('cell_monitor')  # ok
        """) + many,
        "battery/battery/pack.py": """
            import rclpy
            from rclpy.node import Node
            from sensor_msgs.msg import Temperature


            def add_topic(node, name):
                return node.create_publisher(Temperature, name, 10)  # ok


            def main():
                rclpy.init()
                node = Node('pack_monitor')  # ok
                add_topic(node, 'pack/temperature')
                add_topic(node, 'pack/ambient_temperature')
        """,
    })
    check(tmp_path)
