"""ROS007 duplicate-node-name: two creation sites in one file resolving to the same node FQN."""
from rosgraph_spec import codes, findings, graph, messages, node, report

from flake8_rosgraph.graph.model import Location
from flake8_rosgraph.rules.ros007_duplicate_node_name import DuplicateNodeName


def test_two_sites_in_one_file_are_reported_at_the_later_one():
    g = graph(node("camera", path="cams.py", line=10), node("camera", path="cams.py", line=11))
    assert report(g) == ["ROS007 cams.py:11"]
    assert messages(g) == ["ROS007 node '/camera' is also created at cams.py:10"]
    (finding,) = findings(g)
    assert finding.related == ((Location("cams.py", 10, 9), "node '/camera'"),)


def test_three_sites_give_two_findings():
    g = graph(*[node("camera", path="cams.py", line=n) for n in (30, 10, 20)])
    assert report(g) == ["ROS007 cams.py:20", "ROS007 cams.py:30"]


def test_namespaces_make_names_distinct():
    g = graph(node("camera", namespace="/left", path="cams.py", line=10),
              node("camera", namespace="/right", path="cams.py", line=11))
    assert codes(g) == []


def test_same_namespace_written_differently_resolves_the_same():
    g = graph(node("camera", namespace="/left/", path="cams.py", line=10),
              node("camera", namespace="/left", path="cams.py", line=11))
    assert codes(g) == ["ROS007"]


def test_alternatives_of_one_site_do_not_count():
    # One call in a loop or with alternatives yields several nodes at one location.
    g = graph(node("worker", path="pool.py", line=5), node("worker", path="pool.py", line=5, cls="Worker"))
    assert codes(g) == []


def test_sites_in_different_files_are_alternative_executables_by_default():
    g = graph(node("minimal_publisher", path="publisher_old_school.py"),
              node("minimal_publisher", path="publisher_member_function.py"))
    assert codes(g) == []
    assert [f.location.path for f in DuplicateNodeName(across_files=True).check(g, None)] == [
        "publisher_old_school.py"]


def test_unknown_names_are_not_compared():
    g = graph(node(None, path="x.py", line=1), node(None, path="x.py", line=2),
              node("a", namespace=None, path="x.py", line=3), node("a", namespace=None, path="x.py", line=4))
    assert codes(g, select=["ROS007"]) == []
