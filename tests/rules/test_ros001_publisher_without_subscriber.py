"""ROS001 publisher-without-subscriber, on hand-built graphs."""
from rosgraph_spec import codes, findings, graph, messages, node, pub, report, sub

from flake8_rosgraph.graph.model import Location
from flake8_rosgraph.rules import RuleConfig
from flake8_rosgraph.rules.ros001_publisher_without_subscriber import PublisherWithoutSubscriber

INT32 = "std_msgs/msg/Int32"


def thesis_graph():
    """The thesis's four nodes and eight topics (Code 6.7)."""
    return graph(
        node("node_1", sub("/topic1"), sub("/topic3"), pub("/topic7"), pub("/topic1")),
        node("node_2", *[pub(f"/topic{i}") for i in range(1, 8)], sub("/topic7")),
        node("node_3", *[sub(f"/topic{i}") for i in (2, 3, 6, 7, 4, 8)]),
        node("node_4", pub("/topic1"), pub("/topic3"), sub("/topic2")),
    )


def test_thesis_scenario_reports_exactly_the_orphans_and_loops():
    assert report(thesis_graph()) == [
        "ROS002 node_1.py:2",   # node_1 subscribes topic1, which it publishes
        "ROS001 node_2.py:6",   # topic5: published, never subscribed
        "ROS002 node_2.py:9",   # node_2 subscribes topic7, which it publishes
        "ROS003 node_3.py:7",   # topic8: subscribed, never published
    ]


def test_numbered_siblings_are_not_near_misses():
    # '/topic5' and '/topic8' differ by one character, but only in their number.
    assert "ROS001 topic '/topic5' has no subscriber" in messages(thesis_graph())


def connected(*extra):
    """A node that also talks to another node, so its dangling ends are reported."""
    return node("worker", pub("/status"), *extra), node("monitor", sub("/status"))


def test_dangling_publisher_of_a_connected_node():
    assert report(graph(*connected(pub("/debug")))) == ["ROS001 worker.py:3"]


def test_subscribed_topic_is_quiet():
    assert codes(graph(*connected())) == []


def test_subscriber_in_another_file_counts():
    g = graph(node("a", pub("/x"), path="pkg_a/a.py"), node("b", sub("/x"), path="pkg_b/b.py"))
    assert codes(g) == []


def test_subscriber_with_other_type_still_counts_as_subscriber():
    g = graph(*connected(pub("/x")), node("c", sub("/x", type=INT32)))
    assert codes(g, select=["ROS001"]) == []


def test_unresolved_subscription_of_unknown_type_silences():
    g = graph(*connected(pub("/debug")), node("dyn", sub(None, type=None)))
    assert codes(g) == []


def test_unresolved_subscription_of_same_type_silences():
    g = graph(*connected(pub("/debug")), node("dyn", sub(None)))
    assert codes(g) == []


def test_unresolved_subscription_of_other_type_does_not_silence():
    g = graph(*connected(pub("/debug")), node("dyn", sub(None, type=INT32)))
    assert report(g) == ["ROS001 worker.py:3"]


def test_publisher_of_unknown_type_is_silenced_by_any_unresolved_subscription():
    g = graph(*connected(pub("/debug", type=None)), node("dyn", sub(None, type=INT32)))
    assert codes(g) == []


def test_unresolved_publisher_does_not_silence_a_publisher():
    g = graph(*connected(pub("/debug")), node("dyn", pub(None)))
    assert report(g) == ["ROS001 worker.py:3"]


def test_builtin_exempt_topics():
    g = graph(*connected(pub("/tf"), pub("/rosout"), pub("/diagnostics"), pub("/joint_states")))
    assert codes(g) == []


def test_external_names_extend_the_exempt_list():
    g = graph(*connected(pub("/debug"), pub("/robot1/camera/image")))
    assert codes(g, external=["debug", "/*/camera/*"]) == []
    assert report(g, external=["/debug"]) == ["ROS001 worker.py:4"]


def test_stand_alone_node_is_quiet_by_default():
    # A driver whose topics talk to nothing in the workspace: its topics are its interface.
    g = graph(node("gps_driver", pub("/fix"), pub("/vel")))
    assert codes(g) == []


def test_node_whose_publishers_all_leave_the_workspace_is_quiet():
    # It subscribes inside the workspace, but none of its publishers has a subscriber here: outputs for rviz.
    g = graph(node("detector", sub("/image"), pub("/debug_image"), pub("/markers")), node("camera", pub("/image")))
    assert codes(g) == []


def test_connections_through_exempt_names_do_not_make_a_node_talk():
    g = graph(node("gps_driver", pub("/fix"), pub("/tf")), node("viewer", sub("/tf")))
    assert codes(g) == []


def test_self_loop_alone_does_not_make_a_node_talk():
    g = graph(node("echo", pub("/x"), sub("/x"), pub("/fix")))
    assert codes(g, select=["ROS001"]) == []


def test_name_several_nodes_agree_on_is_an_interface():
    # Every example program commands the robot's /cmd_vel, which a C++ driver outside subscribes.
    g = graph(*connected(pub("/cmd_vel")), node("patrol", pub("/cmd_vel"), pub("/status")))
    assert codes(g) == []


def test_alternative_versions_of_one_node_are_one_user():
    g = graph(node("mover", pub("/cmd_vel"), pub("/status"), path="mover_a.py"),
              node("mover", pub("/cmd_vel"), pub("/status"), path="mover_b.py"), node("monitor", sub("/status")))
    assert report(g) == ["ROS001 mover_a.py:2", "ROS001 mover_b.py:2"]


def test_interface_knob_reports_and_says_how_to_declare_the_interface():
    g = graph(node("gps_driver", pub("/fix")))
    (finding,) = PublisherWithoutSubscriber(report_interfaces=True).check(g, RuleConfig())
    assert finding.location == Location("gps_driver.py", 2, 9)
    assert finding.message == ("topic '/fix' has no subscriber in the workspace; if something outside uses it, "
                               "add it to --rosgraph-external-topics")


def test_near_miss_typo_is_reported_with_the_peer_even_between_stand_alone_nodes():
    g = graph(node("teleop", pub("/cmd_vel"), path="teleop/key.py"),
              node("base", sub("/cmdvel"), path="nav/base.py", line=40))
    assert messages(g) == [
        "ROS003 topic '/cmdvel' has no publisher; did you mean '/cmd_vel' (published at teleop/key.py:2)?",
        "ROS001 topic '/cmd_vel' has no subscriber; did you mean '/cmdvel' (subscribed at nav/base.py:41)?",
    ]
    (ros001,) = [f for f in findings(g) if f.code == "ROS001"]
    assert ros001.related == ((Location("nav/base.py", 41, 9), "subscription '/cmdvel'"),)


def test_namespace_slip_is_a_near_miss():
    g = graph(node("lidar", pub("/robot1/scan"), namespace="/robot1"), node("mapper", sub("/scan")))
    assert messages(g, select=["ROS001"]) == [
        "ROS001 topic '/robot1/scan' has no subscriber; did you mean '/scan' (subscribed at mapper.py:2)?"]


def test_near_miss_needs_compatible_types():
    g = graph(node("teleop", pub("/cmd_vel")), node("base", sub("/cmdvel", type=INT32)))
    assert codes(g) == []


def test_near_miss_picks_the_closest_name():
    g = graph(*connected(pub("/camera/image_raw")),
              node("v1", sub("/camera/imag_rw")), node("v2", sub("/camera/image_rw")))
    assert messages(g, select=["ROS001"]) == [
        "ROS001 topic '/camera/image_raw' has no subscriber; did you mean '/camera/image_rw' (subscribed at v2.py:2)?"]


def test_connected_peer_is_still_a_near_miss():
    # '/cmdvel' is subscribed *and* published elsewhere: a typo usually hits a name others use correctly.
    g = graph(*connected(pub("/cmd_vel")), node("base", sub("/cmdvel")), node("joy", pub("/cmdvel")))
    assert messages(g) == [
        "ROS001 topic '/cmd_vel' has no subscriber; did you mean '/cmdvel' (subscribed at base.py:2)?"]


def test_alternatives_of_one_site_are_quiet_if_one_is_connected():
    g = graph(*connected(pub("/scan_sim", line=7), pub("/scan", line=7)), node("mapper", sub("/scan")))
    assert codes(g) == []


def test_alternatives_of_one_site_are_reported_when_all_dangle():
    g = graph(*connected(pub("/a", line=7), pub("/b", line=7)))
    assert messages(g) == ["ROS001 topic '/a' has no subscriber", "ROS001 topic '/b' has no subscriber"]


def test_invalid_name_is_left_to_ros006():
    g = graph(*connected(pub("/a//b", invalid="contains '//'")))
    assert codes(g) == ["ROS006"]


def partly_known(spec_kind, name, line, type=None):
    """The ends of one call whose name is ``name`` on some paths, unknown on others
    (``param if launched else name``): ``name`` marked partial, beside the unknown rest."""
    extra = {} if type is None else {"type": type}
    return spec_kind(name, line=line, partial=True, **extra), spec_kind(None, line=line, **extra)


def test_partly_known_publisher_is_never_reported():
    # Its unknown rest may be subscribed. The same publisher fully known is reported.
    assert codes(graph(*connected(*partly_known(pub, "/debug", 7)))) == []
    assert report(graph(*connected(pub("/debug", line=7)))) == ["ROS001 worker.py:7"]


def test_partly_known_subscription_counts_as_the_subscriber_of_its_known_name():
    # The subscription's unknown rest is of another type, so only its known name can
    # satisfy the Int32 publisher.
    ends = (sub("/count", line=5, type=INT32, partial=True), sub(None, line=5, type="std_msgs/msg/Bool"))
    assert codes(graph(*connected(pub("/count", type=INT32)), node("c", *ends)), select=["ROS001"]) == []
    lone = (sub(None, line=5, type="std_msgs/msg/Bool"),)
    assert report(graph(*connected(pub("/count", type=INT32)), node("c", *lone)), select=["ROS001"]) == [
        "ROS001 worker.py:3"]


def test_hinted_subscription_name_does_not_make_a_near_miss_against_a_publisher():
    # '/cmdvel' would be a near miss of '/cmd_vel' if the subscription's name were known; its
    # unknown rest may be '/cmdvel' itself, so nothing is reported.
    g = graph(*connected(pub("/cmdvel")), node("base", *partly_known(sub, "/cmd_vel", 5)))
    assert codes(g) == []
    known = graph(*connected(pub("/cmdvel")), node("base", sub("/cmd_vel", line=5)))
    assert messages(known, select=["ROS001"]) == [
        "ROS001 topic '/cmdvel' has no subscriber; did you mean '/cmd_vel' (subscribed at base.py:5)?"]


def test_partly_known_ends_do_not_make_a_node_wired():
    # The worker reaches the monitor only through a partly known name: its outputs may all
    # leave the workspace, so its dangling '/debug' is taken for an interface.
    worker = node("worker", pub("/debug"), pub("/status", line=7, partial=True), pub(None, line=7))
    g = graph(worker, node("monitor", sub("/status")))
    assert codes(g, select=["ROS001"]) == []
    wired = node("worker", pub("/debug"), pub("/status", line=7))
    assert report(graph(wired, node("monitor", sub("/status"))), select=["ROS001"]) == ["ROS001 worker.py:2"]
