"""ROS002 self-loop, on hand-built graphs."""
from rosgraph_spec import codes, findings, graph, messages, node, pub, report, sub

from flake8_rosgraph.graph.model import Entity, Location


def test_loop_is_reported_at_the_subscription_with_the_publisher_related():
    g = graph(node("filter", pub("/imu"), sub("/imu")), node("viz", sub("/imu")))
    assert messages(g) == ["ROS002 node '/filter' subscribes to topic '/imu' that it publishes at filter.py:2"]
    (finding,) = findings(g)
    assert finding.location == Location("filter.py", 3, 9)
    assert finding.related == ((Location("filter.py", 2, 9), "publisher '/imu'"),)


def test_every_publisher_of_the_loop_is_related():
    g = graph(node("relay", pub("/x"), pub("/x", line=9), sub("/x")))
    (finding,) = findings(g, select=["ROS002"])
    assert [loc.line for loc, _ in finding.related] == [2, 9]


def test_same_topic_in_two_nodes_is_no_loop():
    assert codes(graph(node("a", pub("/x")), node("b", sub("/x")))) == []


def test_different_topics_are_no_loop():
    g = graph(node("filter", pub("/imu/filtered"), sub("/imu/raw")), node("drv", pub("/imu/raw")),
              node("viz", sub("/imu/filtered")))
    assert codes(g) == []


def test_unresolved_names_never_make_a_loop():
    assert codes(graph(node("n", pub(None), sub(None))), select=["ROS002"]) == []


def test_transform_listener_next_to_a_broadcaster_is_no_loop():
    tf = "tf2_msgs/msg/TFMessage"
    g = graph(node("loc", pub("/tf", type=tf, via="tf2_ros.TransformBroadcaster"),
                   sub("/tf", type=tf, via="tf2_ros.TransformListener")))
    assert codes(g, select=["ROS002"]) == []


def test_subscription_through_a_library_class_still_loops():
    g = graph(node("sync", pub("/image"), sub("/image", via="message_filters.Subscriber")))
    assert report(g, select=["ROS002"]) == ["ROS002 sync.py:3"]


def test_exempt_and_external_names_are_not_loops():
    g = graph(node("loc", pub("/tf"), sub("/tf"), pub("/echo"), sub("/echo")))
    assert report(g, select=["ROS002"]) == ["ROS002 loc.py:5"]
    assert report(g, select=["ROS002"], external=["echo"]) == []


def test_loop_in_each_of_two_nodes_on_other_topics():
    g = graph(node("a", pub("/x"), sub("/x")), node("b", pub("/y"), sub("/y")))
    assert report(g) == ["ROS002 a.py:3", "ROS002 b.py:3"]


def test_a_topic_two_nodes_each_publish_and_subscribe_is_a_shared_bus():
    # A state channel: each node announces on it and listens to the others.
    g = graph(node("a", pub("/state"), sub("/state")), node("b", pub("/state"), sub("/state")))
    assert report(g, select=["ROS002"]) == []
    # One program made under two names (one creation site), or a second node of unknown name,
    # is no second member: ``ros2 doctor hello`` hears its own greetings.
    g = graph(node("hello_a", pub("/canyouhearme"), sub("/canyouhearme"), path="hello.py"),
              node("hello_b", pub("/canyouhearme"), sub("/canyouhearme"), path="hello.py"))
    assert len(report(g, select=["ROS002"])) == 2
    g = graph(node("hello", pub("/canyouhearme"), sub("/canyouhearme"), path="hello.py"),
              node(None, pub("/canyouhearme"), sub("/canyouhearme"), path="other.py"))
    assert len(report(g, select=["ROS002"])) == 2
    # Two nodes of one name are one program's alternatives or instances: each hears only itself.
    g = graph(node("a", pub("/state"), sub("/state")), node("a", pub("/state"), sub("/state"), path="a2.py"))
    assert report(g, select=["ROS002"]) == ["ROS002 a.py:3", "ROS002 a2.py:3"]


def test_ends_added_by_two_executables_to_one_node_class_are_no_loop():
    # driver.py defines the node; reader.py's main publishes on it, parser.py's main subscribes on it.
    n = node("nmea_driver", path="driver.py")
    n.entities += [Entity("publishers", "/sentence", Location("reader.py", 12, 5)),
                   Entity("subscriptions", "/sentence", Location("parser.py", 20, 5))]
    assert codes(graph(n), select=["ROS002"]) == []


def test_end_added_from_another_file_still_loops_with_the_node_file():
    # A helper module creates the publisher on a node passed in; the class subscribes.
    n = node("filter", sub("/imu"), path="filter.py")
    n.entities.append(Entity("publishers", "/imu", Location("helpers.py", 7, 5)))
    assert report(graph(n), select=["ROS002"]) == ["ROS002 filter.py:2"]


def test_partly_known_names_never_make_a_loop():
    # ``topic = param if launched else '/imu'``: the node may subscribe something else.
    hinted = node("filter", pub("/imu"), sub("/imu", line=5, partial=True), sub(None, line=5))
    assert codes(graph(hinted, node("viz", sub("/imu"))), select=["ROS002"]) == []
    known = node("filter", pub("/imu"), sub("/imu", line=5))
    assert codes(graph(known, node("viz", sub("/imu"))), select=["ROS002"]) == ["ROS002"]
