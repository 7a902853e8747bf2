"""ROS006 invalid-name: reports what the graph builder found invalid."""
from rosgraph_spec import codes, graph, messages, node, pub, report

from flake8_rosgraph.graph.model import Entity, Location


def test_invalid_node_name():
    g = graph(node("2nd_camera", invalid="starts with a digit"))
    assert messages(g) == ["ROS006 rcl rejects node '/2nd_camera': starts with a digit"]
    assert report(g) == ["ROS006 2nd_camera.py:1"]


def test_invalid_namespace_shows_namespace_and_name():
    g = graph(node("cam", namespace="/robot//left", invalid="namespace contains '//'"))
    assert messages(g) == ["ROS006 rcl rejects node '/robot//left/cam': namespace contains '//'"]


def test_invalid_topic_shows_the_name_as_written():
    g = graph(node("cam", pub(None, raw_name="camera//image", invalid="contains '//'")))
    assert messages(g) == ["ROS006 rcl rejects topic name 'camera//image': contains '//'"]
    assert report(g) == ["ROS006 cam.py:2"]


def test_invalid_parameter_and_service_names():
    n = node("cam")
    n.entities += [Entity("parameters", "", Location("cam.py", 5, 9), invalid="empty name"),
                   Entity("services", "/a/1b", Location("cam.py", 6, 9), invalid="component starts with a digit")]
    assert messages(graph(n)) == ["ROS006 rcl rejects parameter name '': empty name",
                                  "ROS006 rcl rejects service name '/a/1b': component starts with a digit"]


def test_valid_names_are_quiet():
    assert codes(graph(node("cam", pub("/camera/image")), node("viewer"))) == []


def test_a_name_built_from_the_root_namespace_says_so():
    teleop = node("teleop", pub(None, raw_name="//cmd_vel", invalid="contains '//'"))
    assert messages(graph(teleop)) == [
        "ROS006 rcl rejects topic name '//cmd_vel': contains '//' (built from the node's namespace, "
        "which is the root namespace '/' when nothing sets one: ns + '/x' gives '//x')"]
    launched = node("driver", pub(None, raw_name="//cmd_vel", invalid="contains '//'"))
    launched.launch = {"file": "rover/launch/sim.launch.py", "line": 7}
    assert "as rover/launch/sim.launch.py starts it" in messages(graph(launched))[0]


def test_a_doubled_slash_elsewhere_is_not_blamed_on_the_namespace():
    g = graph(node("cam", pub(None, raw_name="camera//image", invalid="contains '//'"),
                   namespace="/robot1"))
    assert messages(g) == ["ROS006 rcl rejects topic name 'camera//image': contains '//'"]
