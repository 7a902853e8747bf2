"""ROS007 duplicate-node-name: two creation sites of one node FQN that run together."""
from rosgraph_spec import cli, codes, findings, graph, messages, node, pub, report, srv, sub

from flake8_rosgraph.graph.model import Location
from flake8_rosgraph.launch.model import Instance, LaunchedNode, System


def test_two_sites_in_one_file_are_reported_at_both():
    g = graph(node("camera", path="cams.py", line=10), node("camera", path="cams.py", line=11))
    assert report(g) == ["ROS007 cams.py:10", "ROS007 cams.py:11"]
    assert messages(g) == [
        "ROS007 node '/camera' is also created at cams.py:11, and they run together (both are created in this file)",
        "ROS007 node '/camera' is also created at cams.py:10, and they run together (both are created in this file)",
    ]
    later = findings(g)[1]
    assert later.related == ((Location("cams.py", 10, 9), "node '/camera'"),)


def test_three_sites_give_three_findings():
    g = graph(*[node("camera", path="cams.py", line=n) for n in (30, 10, 20)])
    assert report(g) == ["ROS007 cams.py:10", "ROS007 cams.py:20", "ROS007 cams.py:30"]
    assert [len(f.related) for f in findings(g)] == [2, 1, 1]


def test_namespaces_make_names_distinct():
    g = graph(node("camera", namespace="/left", path="cams.py", line=10),
              node("camera", namespace="/right", path="cams.py", line=11))
    assert codes(g) == []


def test_same_namespace_written_differently_resolves_the_same():
    g = graph(node("camera", namespace="/left/", path="cams.py", line=10),
              node("camera", namespace="/left", path="cams.py", line=11))
    assert codes(g) == ["ROS007", "ROS007"]


def test_alternatives_of_one_site_do_not_count():
    # One call in a loop or with alternatives yields several nodes at one location.
    g = graph(node("worker", path="pool.py", line=5), node("worker", path="pool.py", line=5, cls="Worker"))
    assert codes(g) == []


def test_unconnected_sites_in_different_files_are_alternative_programs():
    g = graph(node("minimal_publisher", pub("/topic"), path="publisher_old_school.py"),
              node("minimal_publisher", pub("/topic"), path="publisher_member_function.py"),
              node("minimal_subscriber", sub("/topic"), path="subscriber.py"))
    assert codes(g) == []


def test_nodes_in_two_files_that_talk_to_each_other_are_reported_at_both():
    g = graph(node("camera", pub("/camera/image"), path="camera_driver/driver.py"),
              node("camera", sub("/camera/image"), path="camera_driver/viewer.py"))
    assert report(g) == ["ROS007 camera_driver/driver.py:1", "ROS007 camera_driver/viewer.py:1"]
    assert messages(g)[0] == ("ROS007 node '/camera' is also created at camera_driver/viewer.py:1, "
                              "and they run together (they talk over topic '/camera/image')")


def test_a_service_call_between_them_counts_too():
    g = graph(node("arm", srv("/arm/home"), path="arm/server.py"),
              node("arm", cli("/arm/home"), path="arm/client.py"))
    assert codes(g) == ["ROS007", "ROS007"]


def test_one_node_per_pytest_function_is_quiet():
    # test functions are separate processes: the same name in each of them is no duplicate
    g = graph(*[node("test_node", pub("/probe"), path="my_pkg/test/test_probe.py", line=n) for n in (10, 20, 30)])
    assert codes(g) == []


def test_test_nodes_that_talk_to_each_other_are_reported():
    g = graph(node("fixture", pub("/probe"), path="my_pkg/test/test_probe.py", line=10),
              node("fixture", sub("/probe"), path="my_pkg/test/test_probe.py", line=20))
    assert codes(g) == ["ROS007", "ROS007"]


def launched(system_file, code, line=5, name=None):
    launched_node = LaunchedNode("pkg", "exe", Location(system_file, line, 1), system_file, name=name)
    return Instance(launched_node, code, code)


def instance_of(code, launch_file, line):
    """The node as a launch action at ``launch_file:line`` starts it (the judged graph holds one per action)."""
    started = node(code.name, *[], path=code.location.path, line=code.location.line)
    started.entities = list(code.entities)
    started.launch = {"file": launch_file, "line": line}
    return started


def test_one_executable_launched_twice_under_one_name_is_reported_at_both_actions():
    code = node("scan_pipeline", pub("/scan_filtered"), path="lidar/lidar/filter.py")
    first, second = instance_of(code, "bringup/sensors.launch.py", 8), instance_of(code, "bringup/sensors.launch.py", 9)
    g = graph(first, second)
    g.systems = [System("bringup/sensors.launch.py",
                        instances=[launched("bringup/sensors.launch.py", first, 8, "scan_pipeline"),
                                   launched("bringup/sensors.launch.py", second, 9, "scan_pipeline")])]
    assert report(g) == ["ROS007 bringup/sensors.launch.py:8", "ROS007 bringup/sensors.launch.py:9"]


def test_one_executable_named_alike_in_two_launch_files_is_quiet():
    code = node("scan_pipeline", pub("/scan_filtered"), path="lidar/lidar/filter.py")
    first, second = instance_of(code, "bringup/sim.launch.py", 8), instance_of(code, "bringup/real.launch.py", 8)
    g = graph(first, second)
    g.systems = [System(path, instances=[launched(path, started, 8, "scan_pipeline")])
                 for path, started in (("bringup/sim.launch.py", first), ("bringup/real.launch.py", second))]
    assert codes(g) == []


def test_nodes_started_by_one_launch_file_are_reported():
    a = node("driver", pub("/left/scan"), path="pkg_a/a.py")
    b = node("driver", pub("/right/scan"), path="pkg_b/b.py")
    g = graph(a, b)
    both = [launched("bringup/robot.launch.py", a), launched("bringup/robot.launch.py", b)]
    g.systems = [System("bringup/robot.launch.py", instances=both)]
    assert messages(g, select=["ROS007"]) == [
        "ROS007 node '/driver' is also created at pkg_b/b.py:1, and they run together "
        "(both are started by bringup/robot.launch.py)",
        "ROS007 node '/driver' is also created at pkg_a/a.py:1, and they run together "
        "(both are started by bringup/robot.launch.py)",
    ]


def test_nodes_started_by_different_launch_files_are_quiet():
    a = node("driver", pub("/left/scan"), path="pkg_a/a.py")
    b = node("driver", pub("/right/scan"), path="pkg_b/b.py")
    g = graph(a, b)
    g.systems = [System("bringup/left.launch.py", instances=[launched("bringup/left.launch.py", a)]),
                 System("bringup/right.launch.py", instances=[launched("bringup/right.launch.py", b)])]
    assert codes(g, select=["ROS007"]) == []


def test_unknown_names_are_not_compared():
    g = graph(node(None, path="x.py", line=1), node(None, path="x.py", line=2),
              node("a", namespace=None, path="x.py", line=3), node("a", namespace=None, path="x.py", line=4))
    assert codes(g, select=["ROS007"]) == []


def test_a_launch_name_given_to_an_executable_of_two_nodes_renames_both():
    # One executable creates a broadcaster and a listener; the launch action names it, so rcl
    # gives both nodes that name (``__node:=`` applies to every node of the process).
    broadcaster = node("tf_demo", pub("/tf_demo/pose"), path="demo/demo/nodes.py", line=12)
    listener = node("tf_demo", sub("/tf_demo/pose"), path="demo/demo/nodes.py", line=40)
    action = LaunchedNode("demo", "nodes", Location("bringup/demo.launch.xml", 3, 3), "bringup/demo.launch.xml",
                          name="tf_demo")
    g = graph(broadcaster, listener)
    g.systems = [System("bringup/demo.launch.xml",
                        instances=[Instance(action, broadcaster, broadcaster), Instance(action, listener, listener)])]
    assert report(g, select=["ROS007"]) == ["ROS007 bringup/demo.launch.xml:3"]
    (finding,) = findings(g, select=["ROS007"])
    assert [loc for loc, _ in finding.related] == [Location("demo/demo/nodes.py", 12, 9),
                                                   Location("demo/demo/nodes.py", 40, 9)]
    # The same two nodes under their own names, as written: nothing to report.
    quiet = graph(node("broadcaster", pub("/tf_demo/pose"), path="demo/demo/nodes.py", line=12),
                  node("listener", sub("/tf_demo/pose"), path="demo/demo/nodes.py", line=40))
    assert codes(quiet, select=["ROS007"]) == []


def test_the_nodes_of_one_executable_named_by_two_launch_files_are_two_deployments():
    """Two bring-ups (a lab and a simulation) each start the skill server, an executable of
    two nodes talking over a lease topic, and each names it: the broker of one bring-up and
    the executor of the other are not one system."""
    broker = node("lease_broker", pub("/skill_server/lease_events"), path="skills/skills/broker.py", line=20)
    executor = node("bt_executor", sub("/skill_server/lease_events"), path="skills/skills/executor.py", line=30)
    started = []
    for launch_file in ("bringup/lab.launch.py", "bringup/sim.launch.py"):
        action = LaunchedNode("skills", "skill_server", Location(launch_file, 12, 5), launch_file,
                              name="skill_server")
        for code in (broker, executor):
            instance = instance_of(code, launch_file, 12)
            instance.launch.update(package="skills", executable="skill_server")
            instance.name = "skill_server"
            started.append((launch_file, Instance(action, code, instance), instance))
    g = graph(*(instance for _, _, instance in started))
    g.systems = [System(path, instances=[i for f, i, _ in started if f == path])
                 for path in ("bringup/lab.launch.py", "bringup/sim.launch.py")]
    assert [m for m in messages(g, select=["ROS007"]) if "also created" in m] == []


def test_a_unit_test_node_named_like_a_launched_node_is_no_duplicate():
    """A unit test makes a node of the production node's name to drive its logic; the launch
    file that starts the production node is not part of the test's process. The twin: two
    nodes of one test module that talk are still one process."""
    relay = node("delayed_relay", sub("/number"), pub("/delayed_number"), path="relay/relay/node.py")
    launched_relay = instance_of(relay, "bringup/relay.launch.py", 6)
    test_relay = node("delayed_relay", pub("/number"), path="relay/test/test_relay.py", line=16)
    feeder = node("delayed_relay", sub("/number"), path="relay/test/test_relay.py", line=20)
    g = graph(launched_relay, test_relay)
    g.systems = [System("bringup/relay.launch.py",
                        instances=[launched("bringup/relay.launch.py", launched_relay, 6)])]
    assert codes(g, select=["ROS007"]) == []
    assert report(graph(test_relay, feeder), select=["ROS007"]) == [
        "ROS007 relay/test/test_relay.py:16", "ROS007 relay/test/test_relay.py:20"]


def test_the_transform_tree_and_the_log_tie_no_two_nodes_together():
    """Every node joins ``/tf_static`` (a TransformListener hears every broadcaster) and
    ``/rosout``: two alternative programs of one node name both using them are not one system
    (mrover's navigation and its training project's)."""
    tf = "tf2_msgs/msg/TFMessage"
    g = graph(node("navigation", pub("/tf_static", type=tf), path="rover/nav.py"),
              node("navigation", sub("/tf_static", type=tf), pub("/rosout"), path="starter/nav.py"))
    assert codes(g, select=["ROS007"]) == []


def test_a_simulator_and_a_node_on_its_clock_run_together():
    """``/clock`` ties: the node on simulated time needs that simulator (bitbots' team_comm and
    the MuJoCo simulation)."""
    clock = "rosgraph_msgs/msg/Clock"
    g = graph(node("sim_interface", pub("/clock", type=clock), path="sim/simulation.py"),
              node("sim_interface", sub("/clock", type=clock), path="comm/team_comm.py"))
    assert report(g, select=["ROS007"]) == ["ROS007 comm/team_comm.py:1", "ROS007 sim/simulation.py:1"]
