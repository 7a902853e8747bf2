"""ROS004 message-type-mismatch, on hand-built graphs."""
from rosgraph_spec import acli, asrv, cli, codes, findings, graph, messages, node, pub, report, srv, sub

from flake8_rosgraph.graph.model import Location

STRING = "std_msgs/msg/String"
INT32 = "std_msgs/msg/Int32"


def test_subscription_of_other_type_is_reported_at_the_subscription():
    g = graph(node("a", pub("/status", type=STRING)), node("b", sub("/status", type=INT32)))
    assert messages(g) == ["ROS004 topic '/status' subscribed as 'std_msgs/msg/Int32' "
                           "but published as 'std_msgs/msg/String' at a.py:2"]
    (finding,) = findings(g)
    assert finding.location == Location("b.py", 2, 9)
    assert finding.related == ((Location("a.py", 2, 9), "publisher '/status'"),)


def test_majority_type_wins():
    g = graph(node("a", pub("/status", type=INT32)),
              node("b", sub("/status", type=STRING)), node("c", sub("/status", type=STRING)))
    assert report(g) == ["ROS004 a.py:2"]
    assert messages(g) == ["ROS004 topic '/status' published as 'std_msgs/msg/Int32' "
                           "but subscribed as 'std_msgs/msg/String' at b.py:2"]


def test_two_publishers_disagreeing():
    g = graph(node("a", pub("/x", type=STRING)), node("b", pub("/x", type=INT32)), node("c", sub("/x", type=None)))
    # A tie without a known subscriber type: the alphabetically first type (Int32) is the reference.
    assert messages(g) == ["ROS004 topic '/x' published as 'std_msgs/msg/String' "
                           "but published as 'std_msgs/msg/Int32' at b.py:2"]


def test_node_offering_both_types_is_configurable():
    # if distro == 'humble': Twist, else: TwistStamped -- on one node, as alternatives.
    twist, stamped = "geometry_msgs/msg/Twist", "geometry_msgs/msg/TwistStamped"
    g = graph(node("teleop", pub("/cmd_vel", type=twist, conditional=True),
                   pub("/cmd_vel", type=stamped, conditional=True)),
              node("mover", pub("/cmd_vel", type=twist)), node("base", sub("/cmd_vel", type=twist)))
    assert codes(g) == []
    # Without the agreeing alternative the node is reported.
    g.nodes[0].entities.pop(0)
    assert report(g) == ["ROS004 teleop.py:3"]


def test_unknown_types_are_not_compared():
    g = graph(node("a", pub("/x", type=None)), node("b", sub("/x", type=INT32)), node("c", sub("/x", type=None)))
    assert codes(g) == []


def test_unresolved_names_are_not_compared():
    g = graph(node("a", pub(None, type=STRING)), node("b", sub(None, type=INT32)))
    assert codes(g, select=["ROS004"]) == []


def test_services_and_actions():
    g = graph(node("s", srv("/add", type="example_interfaces/srv/AddTwoInts"),
                   asrv("/fib", type="example_interfaces/action/Fibonacci")),
              node("c", cli("/add", type="std_srvs/srv/Trigger"),
                   acli("/fib", type="nav2_msgs/action/NavigateToPose")))
    assert messages(g) == [
        "ROS004 service '/add' called as 'std_srvs/srv/Trigger' "
        "but served as 'example_interfaces/srv/AddTwoInts' at s.py:2",
        "ROS004 action '/fib' called as 'nav2_msgs/action/NavigateToPose' "
        "but served as 'example_interfaces/action/Fibonacci' at s.py:3",
    ]


def test_topic_and_service_of_the_same_name_are_separate():
    g = graph(node("a", pub("/x", type=STRING), srv("/x", type="std_srvs/srv/Trigger")),
              node("b", sub("/x", type=STRING), cli("/x", type="std_srvs/srv/Trigger")))
    assert codes(g) == []


def test_two_working_systems_of_different_types_are_alternatives_not_a_slip():
    # The same demo twice on one topic: a C++-style pair with images, a Python pair with strings.
    image = "sensor_msgs/msg/Image"
    g = graph(node("talker_cpp", pub("/demo", type=image)), node("listener_cpp", sub("/demo", type=image)),
              node("talker_py", pub("/demo", type=STRING)), node("listener_py", sub("/demo", type=STRING)))
    assert codes(g) == []
    # A third end whose type nobody else speaks is still a mismatch.
    g.nodes.append(node("monitor", sub("/demo", type=INT32)))
    assert report(g) == ["ROS004 monitor.py:2"]


TWIST, STAMPED = "geometry_msgs/msg/Twist", "geometry_msgs/msg/TwistStamped"


def test_one_call_with_several_types_agrees_when_one_of_them_does():
    # ``msg_type = TwistStamped if stamped else Twist``: one subscription, two entities.
    bridge = node("bridge", sub("/cmd_vel", type=TWIST, line=5), sub("/cmd_vel", type=STAMPED, line=5))
    assert codes(graph(bridge, node("teleop", pub("/cmd_vel", type=STAMPED)))) == []
    assert codes(graph(bridge, node("teleop", pub("/cmd_vel", type=TWIST)))) == []
    assert codes(graph(bridge)) == []


def test_one_call_whose_every_type_disagrees_is_reported_once_with_all_of_them():
    bridge = node("bridge", sub("/cmd_vel", type=TWIST, line=5), sub("/cmd_vel", type=STAMPED, line=5))
    g = graph(bridge, node("odom", pub("/cmd_vel", type="nav_msgs/msg/Odometry")))
    assert messages(g) == [
        "ROS004 topic '/cmd_vel' subscribed as 'geometry_msgs/msg/Twist' or 'geometry_msgs/msg/TwistStamped' "
        "but published as 'nav_msgs/msg/Odometry' at odom.py:2"]
    assert report(g) == ["ROS004 bridge.py:5"]

