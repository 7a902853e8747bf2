"""Components loaded into containers are launched nodes: named, namespaced, remapped and
parameterised by their ``ComposableNode`` description, in the pushed namespace (not the
container's), whether the container loads them or ``LoadComposableNodes`` does.
"""
from __future__ import annotations

from pathlib import Path

from flake8_rosgraph.launch.api import judged_graph
from flake8_rosgraph.rules import RuleConfig, run_rules
from launch_workspace import one_system

LAUNCH = '''\
from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes, PushRosNamespace
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    container = ComposableNodeContainer(
        name='vision_container', namespace='perception', package='rclcpp_components',
        executable='component_container',
        composable_node_descriptions=[
            ComposableNode(package='image_proc', plugin='image_proc::RectifyNode', name='rectify',
                           remappings=[('image', 'camera/image_raw')]),
            ComposableNode(package='image_proc', plugin='image_proc::DebayerNode', name='{second}',
                           namespace='{second_ns}', parameters=[{'use_color': True}]),
        ])
    return LaunchDescription([
        GroupAction([
            PushRosNamespace('robot'),
            container,
            LoadComposableNodes(target_container='/robot/perception/vision_container',
                                composable_node_descriptions=[
                                    ComposableNode(package='image_proc', plugin='image_proc::ResizeNode',
                                                   name='resize')]),
        ]),
    ])
'''


def system(tmp_path: Path, second: str = "debayer", second_ns: str = "camera"):
    return one_system(tmp_path, {
        "src/vision_bringup/package.xml": "<package format='3'><name>vision_bringup</name></package>\n",
        "src/vision_bringup/launch/vision.launch.py":
            LAUNCH.replace("{second}", second).replace("{second_ns}", second_ns)})


def test_containers_and_their_components_are_launched(tmp_path):
    _, found = system(tmp_path)
    launched = sorted((n.package, n.executable, n.name, n.namespace, [(r.source, r.target) for r in n.remaps],
                       [(p.name, p.value) for p in n.params]) for n in found.nodes)
    assert launched == [
        ("image_proc", None, "debayer", "/robot/camera", [], [("use_color", True)]),
        ("image_proc", None, "rectify", "/robot", [("image", "camera/image_raw")], []),
        ("image_proc", None, "resize", "/robot", [], []),
        ("rclcpp_components", "component_container", "vision_container", "/robot/perception", [], []),
    ]
    assert found.complete


def test_two_components_with_one_name_in_one_container(tmp_path):
    graph, _ = system(tmp_path, second="rectify", second_ns="camera")
    assert run_rules(judged_graph(graph, graph.systems), RuleConfig(), ["ROS007"]) == []  # /robot/camera
    graph, _ = system(tmp_path / "clash", second="rectify", second_ns="")
    found = run_rules(judged_graph(graph, graph.systems), RuleConfig(), ["ROS007"])
    assert [f.code for f in found] and all("/robot/rectify" in f.message for f in found), found
