"""Entities named by a node's own parameter, and the launch files that set it.

A driver declares ``scan_topic`` with a default and publishes on its value; the launch
file (inline, through a parameter file, or with ``SetParameter``) sets the real name.
The graph keeps the default in code and marks the entity ``from_parameter`` (or, for a name
joined from parameters and text, ``name_template``); where a launch file starts the node,
the values it sets make the name — and where one cannot be read, the name is unknown, never
the default.  What is not known to be built from parameters (a value joined with a constant
on another path, another node's parameter) is never marked.
"""
from __future__ import annotations

from pathlib import Path

from flake8_rosgraph.analysis import analyse, build_graph
from flake8_rosgraph.explain import explain
from flake8_rosgraph.graph.model import Location
from flake8_rosgraph.launch.api import judged_graph

from test_workspace_discovery import PACKAGE_XML, write

SETUP = """
    from setuptools import setup
    setup(name='{name}', packages=['{name}'],
          entry_points={{'console_scripts': [{scripts}]}})
"""


def package(name: str, modules: dict[str, str], scripts: dict[str, str]) -> dict[str, str]:
    files = {f"{name}/package.xml": PACKAGE_XML.format(name=name, build="ament_python"),
             f"{name}/setup.py": SETUP.format(name=name, scripts=", ".join(
                 f"'{exe} = {name}.{module}:main'" for exe, module in scripts.items())),
             f"{name}/{name}/__init__.py": ""}
    files.update({f"{name}/{name}/{module}.py": text for module, text in modules.items()})
    return files


DRIVER = package("lidar", {
    "topics": """
        def output_topic(node, parameter, default):
            node.declare_parameter(parameter, default)
            return node.get_parameter(parameter).get_parameter_value().string_value
    """,
    "driver": """
        import rclpy
        from rclpy.node import Node
        from sensor_msgs.msg import LaserScan
        from std_msgs.msg import String

        from lidar.topics import output_topic


        class Driver(Node):
            def __init__(self):
                super().__init__('lidar_driver')
                self.scan_topic = output_topic(self, 'scan_topic', 'scan')
                self.scan_pub = self.create_publisher(LaserScan, self.scan_topic, 10)
                status = self.declare_parameter('status_topic', 'status').value
                self.create_publisher(String, status, 10)
                prefix = self.declare_parameter('prefix', 'lidar').value
                self.create_publisher(String, prefix + '/diagnostics', 10)
                fallback = self.get_parameter('missing').value or 'heartbeat'
                self.create_publisher(String, fallback, 10)


        def main():
            rclpy.init()
            rclpy.spin(Driver())
    """,
}, {"driver": "driver"})


def named(graph, fqn: str) -> dict[int, set[tuple[str | None, str | None]]]:
    """Per line of the node's publishers and subscriptions: {(name, from_parameter)}."""
    out: dict[int, set] = {}
    for node in graph.nodes:
        if node.fqn == fqn:
            for e in node.entities:
                if e.kind in ("publishers", "subscriptions"):
                    out.setdefault(e.location.line, set()).add((e.name, e.from_parameter))
    return out


def test_a_name_that_is_a_parameter_value_is_marked_and_keeps_its_default(tmp_path: Path):
    graph = build_graph(write(tmp_path, DRIVER))
    driver = next(n for n in graph.nodes if n.fqn == "/lidar_driver")
    assert [e.name_template for e in driver.entities if e.location.line == 17] == [
        (("prefix", "lidar"), ("", "/diagnostics"))]
    assert named(graph, "/lidar_driver") == {
        13: {("/scan", "scan_topic")},       # through a helper in another module and an attribute
        15: {("/status", "status_topic")},   # declare_parameter(...).value
        17: {("/lidar/diagnostics", None)},  # built from the value: a template (below)
        19: {("/heartbeat", None), (None, None)},  # the value or a constant
    }


LAUNCHED = {
    **DRIVER,
    **package("safety", {
        "monitor": """
            import rclpy
            from rclpy.node import Node
            from rclpy.parameter import Parameter
            from sensor_msgs.msg import LaserScan


            class Monitor(Node):
                def __init__(self):
                    super().__init__('monitor')
                    self.declare_parameter('scan_topic', Parameter.Type.STRING)
                    topic = self.get_parameter('scan_topic').value
                    self.create_subscription(LaserScan, topic, print, 10)


            def main():
                rclpy.init()
                rclpy.spin(Monitor())
        """,
    }, {"monitor": "monitor"}),
    "bringup/package.xml": PACKAGE_XML.format(name="bringup", build="ament_python"),
    "bringup/config/front.yaml": """
        /**:
          ros__parameters:
            status_topic: lidar_status
        /front/lidar_driver:
          ros__parameters:
            scan_topic: scan_raw
    """,
    "bringup/launch/front.launch.py": """
        import os

        from ament_index_python.packages import get_package_share_directory
        from launch import LaunchDescription
        from launch.actions import GroupAction
        from launch_ros.actions import Node, PushRosNamespace, SetParameter

        CONFIG = os.path.join(get_package_share_directory('bringup'), 'config', 'front.yaml')


        def generate_launch_description():
            return LaunchDescription([
                GroupAction([
                    PushRosNamespace('front'),
                    SetParameter('scan_topic', 'scan_raw'),
                    Node(package='lidar', executable='driver', parameters=[CONFIG]),
                    Node(package='safety', executable='monitor', parameters=[{'scan_topic': 'scan_raw'}]),
                ]),
            ])
    """,
    "bringup/launch/conflict.launch.py": """
        from launch import LaunchDescription
        from launch.substitutions import LaunchConfiguration
        from launch_ros.actions import Node


        def generate_launch_description():
            return LaunchDescription([
                Node(package='lidar', executable='driver',
                     parameters=[{'scan_topic': '/a'}, {'scan_topic': '/b'}]),
                Node(package='safety', executable='monitor',
                     parameters=[{'scan_topic': LaunchConfiguration('scan')}]),
            ])
    """,
}


def launched(graph, launch_file: str) -> dict[str, dict[int, tuple[str | None, str | None]]]:
    system = next(s for s in graph.systems if s.launch_file.endswith(launch_file))
    judged = judged_graph(graph, [system])
    return {n.fqn: named(judged, n.fqn) for n in judged.nodes if n.launch is not None}


def test_launch_files_and_parameter_files_name_the_entity_where_they_start_the_node(tmp_path: Path):
    graph = build_graph(write(tmp_path, LAUNCHED))
    assert named(graph, "/monitor") == {12: {(None, "scan_topic")}}  # no default: unknown in code
    nodes = launched(graph, "front.launch.py")
    # The scope's SetParameter and the node's file section agree; '/**' names every node.
    assert nodes["/front/lidar_driver"] == {
        13: {("/front/scan_raw", "scan_topic")}, 15: {("/front/lidar_status", "status_topic")},
        17: {("/front/lidar/diagnostics", None)}, 19: {("/front/heartbeat", None), (None, None)}}
    assert nodes["/front/monitor"] == {12: {("/front/scan_raw", "scan_topic")}}
    driver = next(n for n in judged_graph(graph, graph.systems).nodes if n.fqn == "/front/lidar_driver")
    scan = next(e for e in driver.entities if e.location.line == 13)
    assert scan.name_set_at == Location("bringup/launch/front.launch.py", 15, 13)  # the first setting


def test_a_setting_the_analysis_cannot_pin_down_leaves_the_name_unknown(tmp_path: Path):
    graph = build_graph(write(tmp_path, LAUNCHED))
    nodes = launched(graph, "conflict.launch.py")
    assert nodes["/lidar_driver"][13] == {(None, "scan_topic")}  # '/a' then '/b': not guessed
    assert nodes["/lidar_driver"][15] == {("/status", "status_topic")}  # not set: the default
    assert nodes["/monitor"] == {12: {(None, "scan_topic")}}  # a launch argument without a value


def test_another_nodes_parameter_does_not_name_the_entity(tmp_path: Path):
    files = package("bridge", {
        "bridge": """
            import rclpy
            from rclpy.node import Node
            from std_msgs.msg import String


            def main():
                rclpy.init()
                config = Node('bridge_config')
                config.declare_parameter('topic', 'bridged')
                node = Node('bridge')
                node.create_publisher(String, config.get_parameter('topic').value, 10)
                rclpy.spin(node)
        """,
    }, {"bridge": "bridge"})
    graph = build_graph(write(tmp_path, files))
    assert named(graph, "/bridge") == {11: {("/bridged", None)}}


def test_parameters_declared_together_keep_their_defaults_and_names(tmp_path: Path):
    files = package("camera", {
        "camera": """
            import rclpy
            from rclpy.node import Node
            from sensor_msgs.msg import CameraInfo, Image

            OUTPUTS = [('image_topic', 'image_raw'), ('info_topic', 'camera_info')]


            class Camera(Node):
                def __init__(self):
                    super().__init__('camera')
                    self.declare_parameters('', OUTPUTS + [('frame_id', 'camera')])
                    self.declare_parameters('stream', [('topic', 'stream'), ('fps', 30)])
                    image = self.get_parameter('image_topic').value
                    self.create_publisher(Image, image, 10)
                    self.create_publisher(CameraInfo, self.get_parameter('info_topic').value, 10)
                    self.create_publisher(Image, self.get_parameter('stream.topic').value, 10)
                    self.create_publisher(Image, self.get_parameter('topic').value, 10)


            def main():
                rclpy.init()
                rclpy.spin(Camera())
        """,
    }, {"camera": "camera"})
    graph = build_graph(write(tmp_path, files))
    assert named(graph, "/camera") == {
        14: {("/image_raw", "image_topic")}, 15: {("/camera_info", "info_topic")},
        16: {("/stream", "stream.topic")},
        17: {(None, "topic")},  # declared only as 'stream.topic': no default
    }


def test_explain_says_which_parameter_an_unknown_name_is(tmp_path: Path):
    unlaunched = {path: text for path, text in LAUNCHED.items() if not path.startswith("bringup/")}
    graph, analysis = analyse(write(tmp_path, unlaunched))
    report = explain(analysis, graph)
    monitor = next(e for e in report.explanations
                   if e.site.path.endswith("monitor.py") and e.site.line == 12)
    assert monitor.status == "unknown"
    assert any("built from ROS parameter 'scan_topic' of its node, with no default in code that reaches this call" in reason
               for reason in monitor.reasons), monitor.reasons
    driver = [e for e in report.explanations if e.site.path.endswith("driver.py") and e.site.line == 13]
    assert [e.status for e in driver] == ["complete"]  # its default names it


def test_names_joined_from_parameters_follow_the_launch_values(tmp_path: Path):
    files = package("racer", {
        "bridge": """
            import rclpy
            from nav_msgs.msg import Odometry
            from rclpy.node import Node
            from sensor_msgs.msg import LaserScan


            class Bridge(Node):
                def __init__(self):
                    super().__init__('bridge')
                    self.declare_parameter('ego_namespace', 'ego_racecar')
                    self.declare_parameter('odom_topic', 'odom')
                    self.declare_parameter('scan_topic')
                    ns = self.get_parameter('ego_namespace').value
                    odom = ns + '/' + self.get_parameter('odom_topic').value
                    self.create_publisher(Odometry, odom, 10)
                    scan = self.get_parameter('scan_topic').value
                    self.create_publisher(LaserScan, f'/{ns}/{scan}', 10)


            def main():
                rclpy.init()
                rclpy.spin(Bridge())
        """,
    }, {"bridge": "bridge"})
    files["racer/config/sim.yaml"] = """
        bridge:
          ros__parameters:
            ego_namespace: car1
            odom_topic: odometry
            scan_topic: front_scan
    """
    files["racer/launch/sim.launch.py"] = """
        from launch import LaunchDescription
        from launch_ros.actions import Node


        def generate_launch_description():
            return LaunchDescription([
                Node(package='racer', executable='bridge', parameters=['racer/config/sim.yaml']),
            ])
    """
    files["racer/launch/half.launch.py"] = """
        from launch import LaunchDescription
        from launch_ros.actions import Node


        def generate_launch_description():
            return LaunchDescription([
                Node(package='racer', executable='bridge', parameters=[{'ego_namespace': 'car2'}]),
            ])
    """
    graph = build_graph(write(tmp_path, files))
    assert named(graph, "/bridge") == {15: {("/ego_racecar/odom", None)}, 17: {(None, None)}}
    assert launched(graph, "sim.launch.py")["/bridge"] == {
        15: {("/car1/odometry", None)}, 17: {("/car1/front_scan", None)}}
    # Only the namespace set: the odometry topic keeps its default, the scan topic has none.
    assert launched(graph, "half.launch.py")["/bridge"] == {15: {("/car2/odom", None)}, 17: {(None, None)}}


def test_a_setting_the_analysis_cannot_read_is_named_in_a_diagnostic(tmp_path: Path):
    graph = build_graph(write(tmp_path, LAUNCHED))
    system = next(s for s in graph.systems if s.launch_file.endswith("conflict.launch.py"))
    notes = sorted((d.line, d.message) for d in system.problems if "names the entity" in d.message)
    assert [line for line, _ in notes] == [8, 10]  # the driver's two settings, the monitor's argument
    assert notes[1][1].startswith("parameter 'scan_topic' of node '/monitor' names the entity at "
                                  "safety/safety/monitor.py:12, but its value here is not known")
    front = next(s for s in graph.systems if s.launch_file.endswith("front.launch.py"))
    assert not [d for d in front.problems if "names the entity" in d.message]  # every value read
