"""ROS003 subscription-without-publisher, on hand-built graphs."""
from rosgraph_spec import codes, graph, messages, node, pub, report, sub

INT32 = "std_msgs/msg/Int32"


def connected(*extra):
    return node("worker", sub("/cmd"), *extra), node("commander", pub("/cmd"))


def test_dangling_subscription_of_a_connected_node():
    g = graph(*connected(sub("/estop")))
    assert messages(g) == ["ROS003 topic '/estop' has no publisher"]
    assert report(g) == ["ROS003 worker.py:3"]


def test_published_topic_is_quiet():
    assert codes(graph(*connected())) == []


def test_unresolved_publisher_silences_unless_its_type_rules_it_out():
    assert codes(graph(*connected(sub("/estop")), node("dyn", pub(None)))) == []
    assert codes(graph(*connected(sub("/estop")), node("dyn", pub(None, type=None)))) == []
    assert codes(graph(*connected(sub("/estop")), node("dyn", pub(None, type=INT32)))) == ["ROS003"]


def test_unresolved_subscription_does_not_silence_a_subscription():
    assert codes(graph(*connected(sub("/estop")), node("dyn", sub(None)))) == ["ROS003"]


def test_infrastructure_and_rviz_topics_are_exempt():
    g = graph(*connected(sub("/clock"), sub("/tf_static"), sub("/initialpose"), sub("/goal_pose"),
                         sub("/robot_description")))
    assert codes(g) == []


def test_stand_alone_listener_is_quiet():
    assert codes(graph(node("listener", sub("/chatter")))) == []


def test_leading_slash_slip_is_a_near_miss():
    # 'status' written relative inside namespace /arm resolves to /arm/status.
    g = graph(node("arm", sub("/arm/status"), namespace="/arm"), node("hw", pub("/status")))
    assert messages(g, select=["ROS003"]) == [
        "ROS003 topic '/arm/status' has no publisher; did you mean '/status' (published at hw.py:2)?"]


GPS = "sailing_msgs/msg/GPS"


def sailing(gps_topic, *harness):
    """A navigator fed by a simulator, beside a test harness whose topics come from a plan."""
    return graph(
        node("navigate", sub(gps_topic, type=GPS), sub("/wind", type=GPS), pub("/heading"),
             path="src/pathfinding/pathfinding/navigate.py"),
        node("simulator", pub("/gps", type=GPS), pub("/wind", type=GPS), sub("/heading"),
             path="src/simulator/simulator/physics.py"),
        *harness)


def test_an_end_of_unknown_name_and_type_does_not_fill_another_packages_gap():
    harness = node("integration_test", pub(None, type=None), path="src/integration_tests/integration_tests/run.py")
    assert messages(sailing("/sensors/gps", harness), select=["ROS003"]) == [
        "ROS003 topic '/sensors/gps' has no publisher; did you mean '/gps' "
        "(published at src/simulator/simulator/physics.py:2)?"]


def test_an_end_of_unknown_name_and_type_fills_a_gap_of_its_own_package():
    replay = node("replay", pub(None, type=None), path="src/pathfinding/pathfinding/replay.py")
    assert codes(sailing("/sensors/gps", replay), select=["ROS003"]) == []


def test_an_end_of_unknown_name_and_known_type_fills_gaps_anywhere():
    harness = node("integration_test", pub(None, type=GPS), path="src/integration_tests/integration_tests/run.py")
    assert codes(sailing("/sensors/gps", harness), select=["ROS003"]) == []


def test_the_correct_name_is_quiet_beside_the_harness():
    harness = node("integration_test", pub(None, type=None), path="src/integration_tests/integration_tests/run.py")
    assert codes(sailing("/gps", harness), select=["ROS003"]) == []
