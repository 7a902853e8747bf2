"""A node handed to a function by callers the analysis does not see, known by its annotation.

Found on a ninth round of real repositories: helper libraries (``def get_parameters_from(
own_node: Node, other: str)``, ``def call_set_parameters(*, node: rclpy.node.Node, …)``) and
launch tests whose decorator runs ``async def test_smoke(self, node: Node)`` with the node it
made are analysed as entries with unknown arguments, and everything they created on ``node``
was missing from the graph with no trace. rclpy's ``Node`` is now modelled as *passed in*
(``passed_in = true``): such a parameter stands for one node of unknown name and namespace,
located at the function, so absolute names are in the graph and ``--explain`` says why the
node is unknown. Twins: the same helpers called by a node of the workspace stay on that node
only; an unannotated parameter, one annotated with a workspace class, and a helper some code
calls with a node the analysis does not know create no node.
"""
from __future__ import annotations

from pathlib import Path

from test_recall_globals_and_escapes import package
from test_recall_scopes_and_reasons import reasons
from test_workspace_discovery import write

from flake8_rosgraph.analysis import build_graph

HELPERS = """
    import rclpy.node
    from rcl_interfaces.srv import GetParameters
    from rclpy.node import Node
    from sensor_msgs.msg import BatteryState
    from std_msgs.msg import String


    def fetch_remote(own_node: Node, other: str):
        '''The parameter client of another node, made on whichever node asks.'''
        client = own_node.create_client(GetParameters, '/fleet/planner/get_parameters')
        client.wait_for_service(timeout_sec=2.0)
        return client


    def announce_ready(*, node: rclpy.node.Node, text: str = 'ready'):
        pub = node.create_publisher(String, '/fleet/ready', 10)
        pub.publish(String(data=text))


    def watch_battery(node: 'Node', on_state):
        return node.create_subscription(BatteryState, 'battery_state', on_state, 1)


    def untyped_status(node, on_state):
        return node.create_subscription(String, '/fleet/status', on_state, 1)


    def relay(source: Node, sink: Node):
        out = sink.create_publisher(String, '/fleet/relayed', 10)
        return source.create_subscription(String, '/fleet/raw', out.publish, 10)
"""

CONFIG = """
    from rclpy.qos import QoSProfile


    class FleetConfig:
        '''Plain settings object: not a node, whatever its parameter is called.'''

        def __init__(self):
            self.topics = {}

        def create_publisher(self, msg_type, topic, qos):
            self.topics[topic] = msg_type


    def register(node: FleetConfig):
        node.create_publisher(str, '/fleet/config_only', QoSProfile(depth=10))
"""

MANAGER = """
    import rclpy
    from rclpy.node import Node

    from fleet_tools.helpers import announce_ready, fetch_remote, watch_battery


    class FleetManager(Node):
        def __init__(self):
            super().__init__('fleet_manager')
            self.planner_params = fetch_remote(self, 'planner')
            self.battery = watch_battery(self, self.on_battery)
            announce_ready(node=self)

        def on_battery(self, msg):
            self.get_logger().info(str(msg.percentage))


    def main():
        rclpy.init()
        rclpy.spin(FleetManager())
"""

ESCAPED = """
    from fleet_tools.helpers import fetch_remote


    class Reporter:
        '''Holds a node that unknown code hands it later.'''

        def __init__(self, registry):
            self.node = registry.lookup('reporter')

        def refresh(self):
            return fetch_remote(self.node, 'planner')


    def main(registry):
        return Reporter(registry)  # the caller refreshes it
"""


def _workspace(tmp_path: Path, modules: dict[str, str], entries: str = "") -> Path:
    return write(tmp_path, package("fleet_tools", entries, {"helpers": HELPERS, **modules}))


def _nodes(root: Path) -> dict[tuple[str | None, str | None], list[tuple[str, str]]]:
    """``(fqn, passed_in) -> [(kind, name or "?")]`` for every node of the graph."""
    return {(node.fqn, node.passed_in): sorted((e.kind, e.name or "?") for e in node.entities
                                               if e.kind != "timers")
            for node in build_graph(root).nodes}


def test_a_node_parameter_no_analysed_code_fills_is_a_node_of_unknown_name(tmp_path: Path) -> None:
    root = _workspace(tmp_path, {"config": CONFIG})
    assert _nodes(root) == {
        (None, "parameter `own_node` of fetch_remote"): [("clients", "/fleet/planner/get_parameters")],
        (None, "parameter `node` of announce_ready"): [("publishers", "/fleet/ready")],
        # Relative to the caller's namespace: the entity is there, its name is not known.
        (None, "parameter `node` of watch_battery"): [("subscriptions", "?")],
        # Two nodes handed to one function are two nodes, each with what is created on it.
        (None, "parameter `sink` of relay"): [("publishers", "/fleet/relayed")],
        (None, "parameter `source` of relay"): [("subscriptions", "/fleet/raw")],
    }
    found = reasons(root)
    status, why = found[("fleet_tools/fleet_tools/helpers.py", 10)]
    assert status == "unknown"
    assert any("its node is the parameter `own_node` of fetch_remote, annotated as a node" in r
               for r in why)
    status, why = found[("fleet_tools/fleet_tools/helpers.py", 25)]
    assert status == "missing"  # no annotation: still not followed, and said so
    assert any("`node` is not known to be a modelled library object here" in r for r in why)
    # A workspace class of the same shape is not a node: nothing is invented for it.
    status, why = found[("fleet_tools/fleet_tools/config.py", 15)]
    assert status == "missing"
    assert any("`node` is not known to be a modelled library object here" in r for r in why)


def test_helpers_a_workspace_node_calls_stay_on_that_node_only(tmp_path: Path) -> None:
    root = _workspace(tmp_path, {"manager": MANAGER},
                      "'fleet_manager = fleet_tools.manager:main'")
    nodes = _nodes(root)
    assert nodes.pop(("/fleet_manager", None)) == [("clients", "/fleet/planner/get_parameters"),
                                                   ("publishers", "/fleet/ready"),
                                                   ("subscriptions", "/battery_state")]
    # Only the helper nobody calls keeps nodes of its own.
    assert sorted(passed for _, passed in nodes) == ["parameter `sink` of relay",
                                                     "parameter `source` of relay"]


def test_a_helper_called_with_an_unknown_node_gets_no_node_of_its_own(tmp_path: Path) -> None:
    root = _workspace(tmp_path, {"reporter": ESCAPED})
    nodes = _nodes(root)
    # fetch_remote runs on the reporter's unknown node: it is not one of the caller's own.
    assert (None, "parameter `own_node` of fetch_remote") not in nodes
    assert (None, "parameter `node` of announce_ready") in nodes
    status, why = reasons(root)[("fleet_tools/fleet_tools/helpers.py", 10)]
    assert status == "missing"
    assert any("it is created on parameter `own_node` of fetch_remote, a node, which analysed code "
               "passes without the analysis knowing which node it is" in r for r in why)


RUNNER = """
    import functools

    import rclpy
    from rclpy.node import Node


    def run_node_test(test_fn):
        rclpy.init()
        node = Node('bridge_test_client')
        try:
            test_fn(node)
        finally:
            node.destroy_node()
            rclpy.shutdown()


    def node_test(test_fn):
        '''Runs the decorated test with a node of its own (the analysis binds the test itself).'''
        @functools.wraps(test_fn)
        def run(self):
            run_node_test(lambda node: test_fn(self, node))
        return run
"""

SMOKE = """
    import unittest

    from rclpy.node import Node
    from std_msgs.msg import String

    from common import node_test


    class TestBridgeSmoke(unittest.TestCase):
        @node_test
        def test_round_trip(self, node: Node):
            pub = node.create_publisher(String, '/bridge/inbound', 10)
            sub = node.create_subscription(String, '/bridge/outbound', lambda msg: None, 10)
            pub.publish(String(data='ping'))
            self.assertIsNotNone(sub)
"""


def test_a_decorated_launch_test_gets_the_node_its_decorator_passes(tmp_path: Path) -> None:
    root = write(tmp_path, {**package("bridge", "", {}),
                            "bridge/test/common.py": RUNNER, "bridge/test/test_smoke.py": SMOKE})
    nodes = _nodes(root)
    assert nodes[(None, "parameter `node` of TestBridgeSmoke.test_round_trip")] == [
        ("publishers", "/bridge/inbound"), ("subscriptions", "/bridge/outbound")]
