"""``--explain`` reasons and library names found on a ninth round of real repositories.

A client that ros2param's helpers name after the remote node (``{node_name}/set_parameters``)
came out with an unknown name and no reason; a message class imported from a library that
re-exports it (``from tf2_geometry_msgs import PointStamped``) left the publisher's type unknown
with no reason either. The first now names the argument the name is built from, the second is
modelled (tf2_geometry_msgs re-exports geometry_msgs' messages), and a class imported from a
library no stub models says so. Twins: a name the call gives in full stays complete; a class
imported from a workspace module is not called a library's.
"""
from __future__ import annotations

from pathlib import Path

from test_recall_globals_and_escapes import package
from test_recall_scopes_and_reasons import reasons
from test_workspace_discovery import write

from flake8_rosgraph.analysis import build_graph

TUNER = """
    import sys

    import rclpy
    from rcl_interfaces.msg import Parameter, ParameterType, ParameterValue
    from ros2param.api import call_set_parameters


    def push_gain(node, target, gain):
        value = ParameterValue(type=ParameterType.PARAMETER_DOUBLE, double_value=gain)
        call_set_parameters(node=node, node_name=target, parameters=[Parameter(name='gain', value=value)])


    def main():
        rclpy.init()
        node = rclpy.create_node('gain_tuner')
        push_gain(node, sys.argv[1], 0.5)
        call_set_parameters(node=node, node_name='/arm/controller',
                            parameters=[Parameter(name='enabled')])
"""

MARKERS = """
    import rclpy
    from rclpy.node import Node
    from tf2_geometry_msgs import PointStamped
    from ball_tools.shapes import Marker
    from vision_extras import BallHint


    class BallMarkers(Node):
        def __init__(self):
            super().__init__('ball_markers')
            self.point_pub = self.create_publisher(PointStamped, '/ball/point', 1)
            self.marker_pub = self.create_publisher(Marker, '/ball/marker', 1)
            self.hint_pub = self.create_publisher(BallHint, '/ball/hint', 1)


    def main():
        rclpy.init()
        rclpy.spin(BallMarkers())
"""

SHAPES = """
    from visualization_msgs.msg import Marker
"""


def test_a_library_name_built_from_an_argument_says_which(tmp_path: Path) -> None:
    root = write(tmp_path, package("tuning", "'tune = tuning.tuner:main'", {"tuner": TUNER}))
    found = reasons(root)
    status, why = found[("tuning/tuning/tuner.py", 10)]
    assert status == "unknown"
    assert any("parameter `target` of push_gain" in r for r in why)
    assert found[("tuning/tuning/tuner.py", 17)] == ("complete", ())


def test_a_message_reexported_by_tf2_geometry_msgs_is_typed(tmp_path: Path) -> None:
    root = write(tmp_path, package("ball_tools", "'markers = ball_tools.markers:main'",
                                   {"markers": MARKERS, "shapes": SHAPES}))
    types = {e.name: e.type for node in build_graph(root).nodes for e in node.entities}
    assert types["/ball/point"] == "geometry_msgs/msg/PointStamped"
    assert types["/ball/marker"] == "visualization_msgs/msg/Marker"
    assert types["/ball/hint"] is None
    found = reasons(root)
    assert found[("ball_tools/ball_tools/markers.py", 11)] == ("complete", ())
    assert found[("ball_tools/ball_tools/markers.py", 12)] == ("complete", ())
    status, why = found[("ball_tools/ball_tools/markers.py", 13)]
    assert status == "unknown"
    assert any("`BallHint` is imported from `vision_extras`, outside the workspace, which no stub "
               "models" in r for r in why)


LOADER = """
    import importlib


    def get_message_class(name):
        package, _, message = name.partition('/')
        return getattr(importlib.import_module(package + '.msg'), message)
"""

ECHO = """
    import rclpy
    from rclpy.node import Node

    from bridge_tools.loader import get_message_class


    class Echo(Node):
        def __init__(self):
            super().__init__('echo')
            msg_type = 'std_msgs/String'
            self.sub = self.create_subscription(get_message_class(msg_type), '/echo', print, 10)


    def main():
        rclpy.init()
        rclpy.spin(Echo())
"""


def test_a_literal_binding_is_not_given_as_the_cause_of_an_unknown(tmp_path: Path) -> None:
    root = write(tmp_path, package("bridge_tools", "'echo = bridge_tools.echo:main'",
                                   {"loader": LOADER, "echo": ECHO}))
    status, why = reasons(root)[("bridge_tools/bridge_tools/echo.py", 11)]
    assert status == "unknown"
    assert any("it is built from `get_message_class(msg_type)`" in r for r in why)
    assert not any("msg_type = " in r for r in why)
