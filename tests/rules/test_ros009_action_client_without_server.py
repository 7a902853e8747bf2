"""ROS009 action-client-without-server, on hand-built graphs."""
from rosgraph_spec import acli, asrv, codes, graph, messages, node

FIB = "example_interfaces/action/Fibonacci"
NAV = "nav2_msgs/action/NavigateToPose"
DOCK = "opennav_docking_msgs/action/DockRobot"


def connected(*extra):
    """A node whose other action client is served in the workspace, so its unserved ones are reported."""
    return (node("ui", acli("/fibonacci", type=FIB), *extra),
            node("robot", asrv("/fibonacci", type=FIB), asrv("/dock", type=DOCK)))


def test_served_action_client_is_quiet():
    assert codes(graph(*connected())) == []


def test_unserved_action_client():
    g = graph(*connected(acli("/navigate_to_pose", type=NAV)))
    assert messages(g) == ["ROS009 action '/navigate_to_pose' has no server"]


def test_external_action_server():
    g = graph(*connected(acli("/navigate_to_pose", type=NAV)))
    assert codes(g, external=["navigate_to_pose"]) == []


def test_typo_is_a_near_miss():
    g = graph(*connected(acli("/dok", type=DOCK)))
    assert messages(g) == ["ROS009 action '/dok' has no server; did you mean '/dock' (served at robot.py:3)?"]


def test_server_of_another_type_is_no_near_miss():
    g = graph(*connected(acli("/dok", type=NAV)))
    assert messages(g) == ["ROS009 action '/dok' has no server"]


def test_served_name_is_a_near_miss_too():
    # '/fibonacci' already has its client: a second client that misspelt it is still a typo.
    g = graph(*connected(acli("/fibonaci", type=FIB)))
    assert messages(g) == [
        "ROS009 action '/fibonaci' has no server; did you mean '/fibonacci' (served at robot.py:2)?"]


def test_short_names_need_a_plausible_typo():
    # a substitution in a four-letter word is another word; a swap of neighbours is a typo
    assert messages(graph(*connected(acli("/dick", type=DOCK)))) == ["ROS009 action '/dick' has no server"]
    assert messages(graph(*connected(acli("/dcok", type=DOCK)))) == [
        "ROS009 action '/dcok' has no server; did you mean '/dock' (served at robot.py:3)?"]


def test_unresolved_action_server_silences():
    assert codes(graph(*connected(acli("/navigate_to_pose", type=NAV)), node("dyn", asrv(None, type=NAV)))) == []
