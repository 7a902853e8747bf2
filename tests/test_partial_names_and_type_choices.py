"""Two extraction mechanisms on realistic packages, each with the near-identical code where
it must not invent anything:

* a name that is a known constant on some paths and unknown on others (a launch-provided
  parameter, else a default) keeps the constant as a *partly known* entity beside the
  unknown one, and the constant never decides a branch nor builds another name;
* a creation call whose message type is one of several known classes yields one entity
  per class — unless the name has several possibilities too, since which type goes with
  which name is then not known.
"""
from __future__ import annotations

from pathlib import Path

from flake8_rosgraph.analysis import analyse, build_graph
from flake8_rosgraph.explain import explain
from flake8_rosgraph.graph.json_out import to_json_obj

from test_workspace_discovery import PACKAGE_XML, write


def endpoints(root: Path, kind: str = "publishers") -> dict[str | None, list[tuple]]:
    """Per node: (line, name or '?', type or '?', 'partial' or '') of each entity of ``kind``."""
    out: dict[str | None, list[tuple]] = {}
    for node in build_graph(root).nodes:
        out.setdefault(node.fqn, []).extend(sorted(
            (e.location.line, e.name or "?", (e.type or "?").rsplit("/", 1)[-1], "partial" if e.partial else "")
            for e in node.entities if e.kind == kind))
    return out


LIDAR = {
    "lidar/package.xml": PACKAGE_XML.format(name="lidar", build="ament_python"),
    "lidar/setup.py": """
        from setuptools import setup
        setup(name='lidar', packages=['lidar'],
              entry_points={'console_scripts': ['driver = lidar.driver:main']})
    """,
    "lidar/lidar/__init__.py": "",
    "lidar/lidar/params.py": """
        def topic_or_default(node, parameter, default):
            \"\"\"The topic a launch file gives as ``parameter``, else ``default``.\"\"\"
            if node.has_parameter(parameter):
                return node.get_parameter(parameter).value
            return default
    """,
    "lidar/lidar/topics.py": """
        DEFAULT_SCAN_TOPIC = '/scan'
        DEFAULT_STATUS_TOPIC = 'lidar/status'
    """,
    "lidar/lidar/driver.py": """
        import rclpy
        from rclpy.node import Node
        from sensor_msgs.msg import LaserScan
        from std_msgs.msg import String

        from lidar.params import topic_or_default
        from lidar.topics import DEFAULT_SCAN_TOPIC, DEFAULT_STATUS_TOPIC


        class LidarDriver(Node):
            def __init__(self):
                super().__init__('lidar_driver', automatically_declare_parameters_from_overrides=True)
                topic = topic_or_default(self, 'scan_topic', DEFAULT_SCAN_TOPIC)
                self.scan_pub = self.create_publisher(LaserScan, topic, 10)
                self.filtered_pub = self.create_publisher(LaserScan, topic + '/filtered', 10)
                if topic != DEFAULT_SCAN_TOPIC:
                    self.notice_pub = self.create_publisher(String, 'remapped_notice', 1)
                status = topic_or_default(self, 'status_topic', DEFAULT_STATUS_TOPIC)
                self.status_pub = self.create_publisher(String, status, 1)


        def main():
            rclpy.init()
            rclpy.spin(LidarDriver())
    """,
}


def test_a_launch_parameter_or_a_default_keeps_the_default_as_a_partly_known_name(tmp_path: Path) -> None:
    """The helper returns the parameter (unknown) or the default: the default names an entity
    marked partial, beside the unknown rest. Text built from it keeps it the same way
    (``topic + '/filtered'`` is ``/scan/filtered`` on some paths), but the hint is no constant:
    ``topic != DEFAULT_SCAN_TOPIC`` is not decided (the notice publisher exists, on some paths)."""
    root = write(tmp_path, LIDAR)
    assert endpoints(root) == {"/lidar_driver": [
        (14, "/scan", "LaserScan", "partial"), (14, "?", "LaserScan", ""),
        (15, "/scan/filtered", "LaserScan", "partial"), (15, "?", "LaserScan", ""),
        (17, "/remapped_notice", "String", ""),
        (19, "/lidar/status", "String", "partial"), (19, "?", "String", ""),
    ]}
    publishers = to_json_obj(build_graph(root))["nodes"][0]["publishers"]
    assert [(p["topic"], p.get("partial")) for p in publishers if p["line"] == 14] == [(None, None), ("/scan", True)]
    graph, analysis = analyse(root)
    lines = {e.site.line: e.line() for e in explain(analysis, graph).gaps()}
    assert "unknown name (known only partly: '/scan' on some paths, unknown on others)" in lines[14]
    assert "topic_or_default(self, 'scan_topic', DEFAULT_SCAN_TOPIC)" in lines[14]
    assert "unknown name (known only partly: '/scan/filtered' on some paths" in lines[15]


def test_a_name_unknown_on_every_path_stays_unknown(tmp_path: Path) -> None:
    """The same driver whose fallback is unknown too (an environment variable): nothing
    partial is invented."""
    files = dict(LIDAR)
    files["lidar/lidar/topics.py"] = """
        import os

        DEFAULT_SCAN_TOPIC = os.environ['LIDAR_SCAN_TOPIC']
        DEFAULT_STATUS_TOPIC = os.environ.get('LIDAR_STATUS_TOPIC')
    """
    assert endpoints(write(tmp_path, files)) == {"/lidar_driver": [
        (14, "?", "LaserScan", ""), (15, "?", "LaserScan", ""),
        (17, "/remapped_notice", "String", ""),
        (19, "?", "String", ""),
    ]}


def test_a_default_joined_with_an_object_keeps_nothing(tmp_path: Path) -> None:
    """A fallback that is not a constant (a node's own name object) saturates the unknown:
    no partial entity from the other branch's constant."""
    files = dict(LIDAR)
    files["lidar/lidar/topics.py"] = """
        from std_msgs.msg import String

        DEFAULT_SCAN_TOPIC = String
        DEFAULT_STATUS_TOPIC = 'lidar/status'
    """
    assert [e for e in endpoints(write(tmp_path, files))["/lidar_driver"] if e[0] == 14] == [
        (14, "?", "LaserScan", "")]


BRIDGE = {
    "cmd_bridge/package.xml": PACKAGE_XML.format(name="cmd_bridge", build="ament_python"),
    "cmd_bridge/setup.py": """
        from setuptools import setup
        setup(name='cmd_bridge', packages=['cmd_bridge'],
              entry_points={'console_scripts': ['bridge = cmd_bridge.bridge:main']})
    """,
    "cmd_bridge/cmd_bridge/__init__.py": "",
    "cmd_bridge/cmd_bridge/command_types.py": """
        from geometry_msgs.msg import Twist, TwistStamped

        #: What the ``command_type`` parameter selects.
        COMMAND_TYPES = {'twist': Twist, 'stamped': TwistStamped}
    """,
    "cmd_bridge/cmd_bridge/bridge.py": """
        import rclpy
        from rclpy.node import Node
        from geometry_msgs.msg import Twist, TwistStamped
        from rosidl_runtime_py.utilities import get_message

        from cmd_bridge.command_types import COMMAND_TYPES


        class CmdBridge(Node):
            def __init__(self):
                super().__init__('cmd_bridge', automatically_declare_parameters_from_overrides=True)
                msg_type = COMMAND_TYPES[self.get_parameter('command_type').value]
                self.create_subscription(msg_type, 'cmd_vel_in', self.on_command, 10)
                out_type = TwistStamped if self.get_parameter('stamped_out').value else Twist
                self.out = self.create_publisher(out_type, 'cmd_vel_out', 10)
                raw_type = get_message(self.get_parameter('raw_type').value)
                self.raw = self.create_publisher(raw_type, 'cmd_raw', 10)

            def on_command(self, msg):
                self.out.publish(msg)


        def main():
            rclpy.init()
            rclpy.spin(CmdBridge())
    """,
}


def test_a_type_chosen_at_run_time_yields_one_entity_per_type(tmp_path: Path) -> None:
    """A type looked up in a table by a parameter, and one picked by a condition: one
    entity per class; a type an unmodelled call returns stays unknown."""
    root = write(tmp_path, BRIDGE)
    assert endpoints(root, "subscriptions") == {"/cmd_bridge": [
        (13, "/cmd_vel_in", "Twist", ""), (13, "/cmd_vel_in", "TwistStamped", "")]}
    assert endpoints(root) == {"/cmd_bridge": [
        (15, "/cmd_vel_out", "Twist", ""), (15, "/cmd_vel_out", "TwistStamped", ""),
        (17, "/cmd_raw", "?", "")]}
    graph, analysis = analyse(root)
    gaps = {e.site.line for e in explain(analysis, graph).gaps()}
    assert gaps == {17}


RELAY = {
    "relay/package.xml": PACKAGE_XML.format(name="relay", build="ament_python"),
    "relay/relay/__init__.py": "",
    "relay/relay/table.py": """
        from nav_msgs.msg import Odometry
        from sensor_msgs.msg import LaserScan

        RELAYED = {'front/scan': LaserScan, 'odom': Odometry}
        ONE_TYPE = {'front/scan': LaserScan, 'rear/scan': LaserScan}
    """,
    "relay/relay/relay.py": """
        import rclpy
        from rclpy.node import Node

        from relay.table import ONE_TYPE, RELAYED


        class Relay(Node):
            def __init__(self):
                super().__init__('relay')
                self.pubs = {}
                for name, msg_type in RELAYED.items():
                    self.pubs[name] = self.create_publisher(msg_type, 'relayed/' + name, 10)
                for name, msg_type in ONE_TYPE.items():
                    self.create_subscription(msg_type, name, self.on_scan, 10)

            def on_scan(self, msg):
                pass


        def main():
            rclpy.init()
            rclpy.spin(Relay())
    """,
}


def test_a_name_to_type_table_does_not_pair_every_name_with_every_type(tmp_path: Path) -> None:
    """Iterating ``{name: type}`` gives the loop body every name and every type at once:
    pairing them all would invent ``/relayed/odom`` as a LaserScan. The creation call runs
    once per row of the written-out table instead, each name with its own type (see
    test_recall_scopes_and_reasons.py for tables the rows cannot be followed through)."""
    root = write(tmp_path, RELAY)
    assert endpoints(root) == {"/relay": [
        (12, "/relayed/front/scan", "LaserScan", ""), (12, "/relayed/odom", "Odometry", "")]}
    assert endpoints(root, "subscriptions") == {"/relay": [
        (14, "/front/scan", "LaserScan", ""), (14, "/rear/scan", "LaserScan", "")]}


def test_a_guarded_empty_default_is_no_partly_known_name(tmp_path: Path) -> None:
    """``topic = param or ''`` then ``if topic:``: the empty default never reaches the call,
    but the analysis does not decide branches on a partly known value. A known alternative
    that is no valid name is dropped rather than shown (and reported by ROS006) as the
    name of an entity; the unknown rest stays."""
    files = dict(LIDAR)
    files["lidar/lidar/topics.py"] = """
        DEFAULT_SCAN_TOPIC = ''
        DEFAULT_STATUS_TOPIC = 'lidar/status'
    """
    assert [e for e in endpoints(write(tmp_path, files))["/lidar_driver"] if e[0] == 14] == [
        (14, "?", "LaserScan", "")]
