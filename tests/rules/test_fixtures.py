"""Test fixtures form their own systems: they connect among themselves and with what they test, never
with production nodes of other packages, and never make a production end look connected."""
import pytest
from rosgraph_spec import graph, messages, node, pub, sub

from flake8_rosgraph.rules.fixtures import node_scope, fixture_scope


@pytest.mark.parametrize("path, scope", [
    ("odom_filter/test/test_filter.py", "odom_filter/"),
    ("src/nav/tests/fixtures/fake_map.py", "src/nav/"),
    ("nav/nav/test_utils.py", "nav/nav/"),
    ("nav/nav/planner_test.py", "nav/nav/"),
    ("test/conftest.py", ""),
    ("nav/nav/testing.py", None),
    ("nav/nav/contest/test.py", None),   # a module named test.py is not a pytest module
])
def test_test_scope(path, scope):
    assert fixture_scope(path) == scope


def test_a_production_node_started_by_a_launch_test_is_part_of_that_test():
    launched = node("filter", path="odom_filter/odom_filter/filter.py")
    launched.launch = {"file": "odom_filter/test/test_filter.launch.py", "line": 12}
    assert node_scope(launched) == "odom_filter/"
    launched.launch = {"file": "odom_filter/launch/filter.launch.py", "line": 12}
    assert node_scope(launched) is None


def production(*extra):
    """A filter that feeds a planner (so its ends are judged) and a publisher with a typo."""
    return (node("filter", pub("/odom_filterd"), pub("/status"), path="odom_filter/odom_filter/filter.py"),
            node("planner", sub("/odom_filtered"), sub("/status"), path="planner/planner/planner.py"), *extra)


def test_a_test_subscriber_does_not_connect_a_production_typo():
    probe = node("probe", sub("/odom_filterd"), path="odom_filter/test/test_filter.py")
    assert messages(graph(*production(probe)), select=["ROS001"]) == [
        "ROS001 topic '/odom_filterd' has no subscriber; did you mean '/odom_filtered' "
        "(subscribed at planner/planner/planner.py:2)?"]


def test_a_fixture_connects_to_the_package_it_tests():
    # the probe listens to its own package's filter: connected, quiet
    probe = node("probe", sub("/odom_filterd"), sub("/status"), path="odom_filter/test/test_filter.py")
    assert messages(graph(*production(probe)), select=["ROS003"]) == [
        "ROS003 topic '/odom_filtered' has no publisher; did you mean '/odom_filterd' "
        "(published at odom_filter/odom_filter/filter.py:2)?"]


def test_a_fixture_does_not_connect_to_other_packages():
    # a fake map server in the planner's tests does not feed the filter package's probe
    fake = node("fake_map", pub("/map"), path="planner/test/test_planner.py")
    probe = node("probe", sub("/map"), sub("/status"), path="odom_filter/test/test_filter.py")
    assert [m for m in messages(graph(*production(fake, probe)), select=["ROS003"]) if "'/map'" in m] == [
        "ROS003 topic '/map' has no publisher"]
    fake.location = type(fake.location)("odom_filter/test/test_filter.py", 40, 9)
    assert [m for m in messages(graph(*production(fake, probe)), select=["ROS003"]) if "'/map'" in m] == []


def test_fixtures_of_one_package_see_each_other():
    talker = node("fake_talker", pub("/chatter"), pub("/ack"), path="demo/test/test_pair.py", line=10)
    listener = node("fake_listener", sub("/chatter"), sub("/ack"), path="demo/test/test_pair.py", line=20)
    assert messages(graph(talker, listener)) == []


def test_production_unknowns_are_not_filled_by_a_fixture():
    # a fixture subscribing to a name the analysis could not resolve does not excuse a production end
    unknown = node("probe", sub(None), path="odom_filter/test/test_filter.py")
    assert "ROS001" in " ".join(messages(graph(*production(unknown)), select=["ROS001"]))


def test_two_launch_test_modules_never_run_together():
    # launch_testing's ``*.test.py`` modules (CMake's add_launch_test) are test runs of their own,
    # like ``test_*.py``: a best-effort publisher in one never meets a reliable subscription in another
    best_effort = node(None, pub("/a_topic", qos={"reliability": "best_effort"}),
                       path="bridge_server/test/websocket/best_effort.test.py", namespace=None)
    smoke = node(None, sub("/a_topic", qos={"reliability": "reliable"}),
                 path="bridge_server/test/websocket/smoke.test.py", namespace=None)
    assert messages(graph(best_effort, smoke), select=["ROS005"]) == []
    smoke.location = type(smoke.location)("bridge_server/test/websocket/best_effort.test.py", 40, 9)
    assert [m[:6] for m in messages(graph(best_effort, smoke), select=["ROS005"])] == ["ROS005"]
