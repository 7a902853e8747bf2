"""``OpaqueFunction``: the actions its function returns are launched; what it reads from the
launch context at run time is unknown, so names built from it are unresolved, never guessed."""
from __future__ import annotations

from pathlib import Path

from launch_workspace import one_system

LAUNCH = '''\
from launch import LaunchDescription
from launch.actions import OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from fleet_tools.launching import external_actions  # not in the workspace



def robots(context):
    return [Node(package='fleet', executable='agent', namespace='alpha'),
            Node(package='fleet', executable='agent', namespace='beta')]


def chosen(context, *args, **kwargs):
    robot = LaunchConfiguration('robot').perform(context)
    return [Node(package='fleet', executable='agent', namespace=robot)]


def generate_launch_description():
    return LaunchDescription([
        OpaqueFunction(function=robots),
        OpaqueFunction(function=chosen),
        OpaqueFunction(function=lambda context: print('starting')),  # returns None: launches nothing
        OpaqueFunction(function=external_actions),
    ])
'''


def test_actions_an_opaque_function_returns_are_launched(tmp_path: Path) -> None:
    _, system = one_system(tmp_path, {"src/fleet/package.xml": "<package format='3'><name>fleet</name></package>\n",
                                      "src/fleet/launch/fleet.launch.py": LAUNCH})
    launched = sorted((n.namespace or "?", bool(n.unresolved)) for n in system.nodes)
    assert launched == [("/alpha", False), ("/beta", False), ("?", True)]
    assert [p.message for p in system.problems] == [
        "OpaqueFunction of a function the analysis cannot determine is not followed: nodes it starts "
        "are not in the system"]


BRANCHED = '''\
from launch import LaunchDescription
from launch.actions import OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def run_detector(context, use_tracking):
    tracking = LaunchConfiguration(use_tracking).perform(context) == 'True'
    detections = 'tracking' if tracking else 'detections'
    return [Node(package='vision', executable='debug_node', name='debug_node', namespace='vision',
                 remappings=[('image_raw', '/camera/image_raw'), ('detections', detections)])]


def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=run_detector, args=['use_tracking'])])
'''


def test_a_list_built_on_two_branches_is_joined_entry_by_entry(tmp_path: Path) -> None:
    """The remap both branches agree on is applied once; the one they disagree on is unresolved."""
    _, system = one_system(tmp_path, {"src/vision/package.xml": "<package format='3'><name>vision</name></package>\n",
                                      "src/vision/launch/detect.launch.py": BRANCHED})
    (node,) = system.nodes
    assert [(r.source, r.target) for r in node.remaps] == [("image_raw", "/camera/image_raw")]
    assert node.unresolved == ["remap: a value with several possible values"]
