"""Actions inside ``RegisterEventHandler``: launched when the event comes, so conditional, never dropped.

A typical bringup starts a controller spawner and, once it exits, the nodes that
need the controller; a misspelt executable there must be found like anywhere else.
"""
from __future__ import annotations

from pathlib import Path

from flake8_rosgraph.launch.api import judged_graph
from flake8_rosgraph.rules import RuleConfig, run_rules
from launch_workspace import one_system

BRINGUP = '''\
from launch import LaunchDescription
from launch.actions import RegisterEventHandler
from launch.event_handlers import OnProcessExit, OnProcessStart
from launch_ros.actions import Node


def generate_launch_description():
    spawner = Node(package='arm', executable='spawner', namespace='arm')
    return LaunchDescription([
        spawner,
        RegisterEventHandler(OnProcessExit(
            target_action=spawner,
            on_exit=[Node(package='arm', executable='{after_exit}', namespace='arm')])),
        RegisterEventHandler(event_handler=OnProcessStart(
            target_action=spawner,
            on_start=[Node(package='arm', executable='monitor', namespace='arm')])),
        RegisterEventHandler(OnProcessExit(target_action=spawner, on_exit=lambda event, context: [])),
    ])
'''

SETUP = '''\
from setuptools import setup

setup(name='arm', packages=['arm'], entry_points={'console_scripts': [
    'spawner = arm.tools:main', 'controller_client = arm.tools:main', 'monitor = arm.tools:main']})
'''

TOOLS = '''\
import rclpy
from rclpy.node import Node


def main():
    rclpy.init()
    rclpy.spin(Node('arm_tool'))
'''


def bringup(tmp_path: Path, after_exit: str):
    files = {"src/arm/package.xml": "<package format='3'><name>arm</name></package>\n",
             "src/arm/setup.py": SETUP, "src/arm/arm/__init__.py": "", "src/arm/arm/tools.py": TOOLS,
             "src/arm/launch/bringup.launch.py": BRINGUP.replace("{after_exit}", after_exit)}
    return one_system(tmp_path, files)


def test_actions_of_event_handlers_are_launched_conditionally(tmp_path):
    graph, system = bringup(tmp_path, "controller_client")
    launched = sorted((n.executable, n.namespace, n.conditional) for n in system.nodes)
    assert launched == [("controller_client", "/arm", True), ("monitor", "/arm", True),
                        ("spawner", "/arm", False)]
    assert [p.message for p in system.problems] == [
        "a launch entity the analysis cannot determine is not followed: nodes it starts are not in the system"]
    assert run_rules(judged_graph(graph, graph.systems), RuleConfig(), ["ROS201"]) == []


def test_a_misspelt_executable_after_an_event_is_found(tmp_path):
    graph, _ = bringup(tmp_path, "controler_client")
    found = run_rules(judged_graph(graph, graph.systems), RuleConfig(), ["ROS201"])
    assert [(f.code, f.location.line) for f in found] == [("ROS201", 13)]
    assert "did you mean 'controller_client'" in found[0].message
