"""ROS008 service-client-without-server, on hand-built graphs."""
from rosgraph_spec import cli, codes, findings, graph, messages, node, pub, report, srv, sub

from flake8_rosgraph.graph.model import Location

ADD = "example_interfaces/srv/AddTwoInts"
TRIGGER = "std_srvs/srv/Trigger"


def connected(*extra):
    """A client node that already calls a server of the workspace, so its unserved clients are reported."""
    return (node("ui", cli("/add_two_ints", type=ADD), *extra),
            node("robot", srv("/add_two_ints", type=ADD), srv("/add_three_ints", type=ADD)))


def test_served_client_is_quiet():
    assert codes(graph(*connected())) == []


def test_unserved_client_of_a_connected_node():
    g = graph(*connected(cli("/reset", type=TRIGGER)))
    assert messages(g) == ["ROS008 service '/reset' has no server"]
    assert report(g) == ["ROS008 ui.py:3"]


def test_typo_is_a_near_miss_with_the_server_related():
    g = graph(*connected(cli("/add_three_int", type=ADD)))
    assert messages(g) == [
        "ROS008 service '/add_three_int' has no server; did you mean '/add_three_ints' (served at robot.py:3)?"]
    (finding,) = findings(g)
    assert finding.related == ((Location("robot.py", 3, 9), "service server '/add_three_ints'"),)


def test_builtin_per_node_services_are_exempt():
    g = graph(*connected(cli("/robot/get_parameters"), cli("/ns/robot/set_parameters"),
                         cli("/cam/change_state"), cli("/LoggerServiceNode/get_logger_levels")))
    assert codes(g) == []


def test_per_node_service_patterns_need_a_node_prefix():
    # A service literally named '/get_parameters' is nobody's parameter service.
    assert codes(graph(*connected(cli("/get_parameters")))) == ["ROS008"]


def test_unresolved_server_silences():
    assert codes(graph(*connected(cli("/reset", type=TRIGGER)), node("dyn", srv(None, type=None)))) == []


def test_stand_alone_client_is_quiet():
    assert codes(graph(node("caller", cli("/reset", type=TRIGGER)))) == []


def test_client_node_wired_only_through_topics_is_quiet():
    # None of this node's clients reaches a server of the workspace: its services live elsewhere.
    g = graph(node("ui", pub("/cmd"), cli("/reset", type=TRIGGER)), node("robot", sub("/cmd")))
    assert codes(g) == []


def test_services_of_another_node_namespace_are_its_interface():
    g = graph(*connected(cli("/local_costmap/clear_entirely", type=TRIGGER),
                         cli("/local_costmap/clear_around_robot", type=TRIGGER)))
    assert codes(g) == []
