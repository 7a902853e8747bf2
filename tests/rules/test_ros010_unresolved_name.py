"""ROS010 unresolved-name: off by default, lists the blind spots when selected."""
from rosgraph_spec import cli, codes, graph, messages, node, pub, sub

from flake8_rosgraph.graph.model import Entity, Location


def blind_spots():
    n = node("dyn", pub(None), sub("/ok"), cli(None))
    n.entities.append(Entity("timers", None, Location("dyn.py", 9, 9), period=1.0))
    n.entities.append(Entity("parameters", "rate", Location("dyn.py", 10, 9), default=1.0))
    return graph(n, node(None, path="anon.py"), node("x", namespace=None, path="x.py"))


def test_off_by_default():
    assert "ROS010" not in codes(blind_spots())


def test_selected_lists_unresolved_nodes_and_named_entities_only():
    assert messages(blind_spots(), select=["ROS010"]) == [
        "ROS010 node name cannot be determined statically",
        "ROS010 topic name of publisher cannot be determined statically",
        "ROS010 service name of service client cannot be determined statically",
        "ROS010 namespace of node 'x' cannot be determined statically",
    ]


def test_the_message_names_the_expression_as_written(tmp_path):
    """ROS010 quotes the argument the analysis could not evaluate, so the user sees what to fix."""
    from flake8_rosgraph.analysis import build_graph
    from flake8_rosgraph.rules import RuleConfig, run_rules

    (tmp_path / "relay.py").write_text(
        "import sys\nimport rclpy\nfrom std_msgs.msg import String\n\n"
        "rclpy.init()\nnode = rclpy.create_node('relay')\n"
        "node.create_publisher(String, sys.argv[1] + '/out', 10)\n"
        "node.create_subscription(String, topic='/in', callback=print, qos_profile=10)\n")
    messages = [f.message for f in run_rules(build_graph(tmp_path), RuleConfig(), ["ROS010"])]
    assert messages == ["topic name of publisher cannot be determined statically: `sys.argv[1] + '/out'`"]
