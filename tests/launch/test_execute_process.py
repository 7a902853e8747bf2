"""``ExecuteProcess`` of a package's executable starts a node like ``Node`` does.

Demo and test launch files run ``ExecutableInPackage(...)`` or ``ros2 run pkg exe``
with ``--ros-args``: the node, its namespace, name, remaps and parameters are read
from the command. Any other program (``xacro``, ``gz sim``) stays a named gap.
"""
from __future__ import annotations

from pathlib import Path

from flake8_rosgraph.launch.api import judged_graph
from flake8_rosgraph.rules import RuleConfig, run_rules
from launch_workspace import one_system

LAUNCH = '''\
from launch import LaunchDescription
from launch.actions import ExecuteProcess
from launch_ros.substitutions import ExecutableInPackage


def generate_launch_description():
    publisher = ExecutableInPackage(package='monitor', executable='data_publisher')
    return LaunchDescription([
        ExecuteProcess(cmd=[publisher, 'sensor', '--best-effort'], output='screen'),
        ExecuteProcess(cmd=['ros2', 'run', 'monitor', '{listener}', '--ros-args',
                            '-r', '__ns:=/robot', '-r', '__node:=watcher', '-r', 'data:={topic}',
                            '-p', 'rate:=2.5'], output='screen'),
        ExecuteProcess(cmd=['xacro', '-o', '/tmp/robot.urdf', 'robot.xacro']),
    ])
'''

NODES = '''\
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Publisher(Node):
    def __init__(self):
        super().__init__('data_publisher', namespace='robot')
        self.create_publisher(String, 'sensor_data', 10)


class Listener(Node):
    def __init__(self):
        super().__init__('listener')
        self.declare_parameter('rate', 1.0)
        self.create_subscription(String, 'data', print, 10)


def publish():
    rclpy.init()
    rclpy.spin(Publisher())


def listen():
    rclpy.init()
    rclpy.spin(Listener())
'''

SETUP = '''\
from setuptools import setup

setup(name='monitor', packages=['monitor'], entry_points={'console_scripts': [
    'data_publisher = monitor.nodes:publish', 'listener = monitor.nodes:listen']})
'''


def demo(tmp_path: Path, listener: str = "listener", topic: str = "sensor_data"):
    files = {"src/monitor/package.xml": "<package format='3'><name>monitor</name></package>\n",
             "src/monitor/setup.py": SETUP, "src/monitor/monitor/__init__.py": "",
             "src/monitor/monitor/nodes.py": NODES,
             "src/monitor/launch/demo.launch.py": LAUNCH.replace("{listener}", listener).replace("{topic}", topic)}
    return one_system(tmp_path, files)


def test_package_executables_run_as_processes_are_nodes(tmp_path):
    graph, system = demo(tmp_path)
    launched = sorted((n.executable, n.name, n.namespace, [(r.source, r.target) for r in n.remaps],
                       [(p.name, p.value) for p in n.params]) for n in system.nodes)
    assert launched == [("data_publisher", None, None, [], []),
                        ("listener", "watcher", "/robot", [("data", "sensor_data")], [("rate", 2.5)])]
    assert [p.message for p in system.problems] == [
        "ExecuteProcess is not followed: nodes it starts are not in the system"]
    judged = judged_graph(graph, graph.systems)
    assert "/robot/watcher" in {n.fqn for n in judged.nodes}
    assert run_rules(judged, RuleConfig(), ["ROS201", "ROS003"]) == []


def test_the_command_line_is_judged_like_a_node_action(tmp_path):
    graph, _ = demo(tmp_path, listener="listner", topic="sensor_dat")
    found = run_rules(judged_graph(graph, graph.systems), RuleConfig(), ["ROS201"])
    assert [f.message for f in found] == [
        "package 'monitor' has no executable 'listner'; did you mean 'listener'?"]
