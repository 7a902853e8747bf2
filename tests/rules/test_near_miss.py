"""The near-miss hint against every name of the other role: which slips it recognises, which names it leaves alone."""
import random

import pytest
from rosgraph_spec import acli, asrv, cli, graph, messages, node, pub, srv, sub

from flake8_rosgraph.rules.near_miss import folded, is_family, token_typo, transposition_distance

FIB = "example_interfaces/action/Fibonacci"
TRIGGER = "std_srvs/srv/Trigger"


def chatter(*listeners):
    """A talker whose /chatter keeps a correct listener, plus the given nodes."""
    return graph(node("talker", pub("/chatter"), sub("/ack"), path="demo/talker.py"),
                 node("listener", sub("/chatter"), pub("/ack"), path="demo/listener.py"), *listeners)


def recorder(*specs):
    """A node that talks to the workspace through /ack, so its other ends are judged."""
    return node("recorder", sub("/ack"), *specs, path="demo/recorder.py")


@pytest.mark.parametrize("typo", ["/chater", "/chattre", "/chatterr", "/Chatter", "/chatters"])
def test_a_typo_of_a_name_that_keeps_a_listener_is_reported(typo):
    assert messages(chatter(recorder(sub(typo))), select=["ROS003"]) == [
        f"ROS003 topic '{typo}' has no publisher; did you mean '/chatter' (published at demo/talker.py:2)?"]


def test_the_correct_second_listener_stays_quiet():
    assert messages(chatter(recorder(sub("/chatter")))) == []


def test_private_slip_is_matched_through_the_written_name():
    g = chatter(node("logger", sub("/ack"), sub("/ns/logger/chatter", raw_name="~/chatter"),
                     namespace="/ns", path="demo/logger.py"),
                node("ns_talker", pub("/ns/chatter"), path="demo/ns_talker.py"))
    # '/ns/logger/chatter' was written '~/chatter': '/ns/chatter' is one token away, '/chatter' two
    assert messages(g, select=["ROS003"]) == [
        "ROS003 topic '/ns/logger/chatter' has no publisher; did you mean '/ns/chatter' "
        "(published at demo/ns_talker.py:2)?"]


def test_absolute_slip_two_tokens_away_is_found_by_resolution():
    g = chatter(node("logger", sub("/ack"), sub("/ns/logger/chatter", raw_name="~/chatter"),
                     namespace="/ns", path="demo/logger.py"))
    assert messages(g, select=["ROS003"]) == [
        "ROS003 topic '/ns/logger/chatter' has no publisher; did you mean '/chatter' (published at demo/talker.py:2)?"]


def test_a_dropped_namespace_token():
    g = chatter(recorder(sub("/robot/chatter")))
    assert messages(g, select=["ROS003"]) == [
        "ROS003 topic '/robot/chatter' has no publisher; did you mean '/chatter' (published at demo/talker.py:2)?"]


def detector(topic):
    """A QR detector publishing its delta under its package's namespace, and a navigator
    (fed by the workspace through /ack) that subscribes to ``topic``."""
    delta = "deepracer_interfaces_pkg/msg/DetectionDeltaMsg"
    return graph(node("qr_detection_node", pub("/qr_detection_pkg/delta", type=delta), pub("/ack"),
                      namespace="/qr_detection_pkg", path="qr/qr_node.py"),
                 node("navigation_node", sub(topic, type=delta), sub("/ack"), path="nav/nav_node.py"))


def test_a_namespace_token_with_one_word_dropped_is_a_near_miss():
    """Seeded in aws-deepracer-offroad: ``/qr_detection`` for the package namespace
    ``/qr_detection_pkg``: a whole ``_pkg`` is no typo, but the token is that word short."""
    assert messages(detector("/qr_detection/delta"), select=["ROS003"]) == [
        "ROS003 topic '/qr_detection/delta' has no publisher; did you mean '/qr_detection_pkg/delta' "
        "(published at qr/qr_node.py:2)?"]


@pytest.mark.parametrize("topic", ["/qr_reader/delta", "/detection_pkg_qr/delta", "/qr_detection_pkg/delta_x"])
def test_another_word_in_a_namespace_token_or_the_leaf_is_no_near_miss(topic):
    """A word replaced (``qr_reader``), words moved, or a word added to the last token (that
    is another name, ``/odom`` and ``/odom_raw``) are not the one-word slip."""
    assert "did you mean" not in " ".join(messages(detector(topic), select=["ROS003"]))


def test_same_leaf_in_another_namespace_is_a_family_not_a_slip():
    g = graph(node("left", pub("/left/image"), pub("/ack"), path="cam/left.py"),
              node("viewer", sub("/right/image"), sub("/ack"), path="cam/viewer.py"))
    assert messages(g, select=["ROS001"]) == ["ROS001 topic '/left/image' has no subscriber"]


@pytest.mark.parametrize("intended, other", [("/robot1/odom", "/robot2/odom"), ("/cmd", "/cmd2"),
                                             ("/topic5", "/topic8")])
def test_numbered_families_are_never_near_misses(intended, other):
    g = graph(node("sim", pub(intended), sub("/ack"), path="sim.py"),
              node("monitor", sub(other), pub("/ack"), path="monitor.py"))
    assert all("did you mean" not in m for m in messages(g))


@pytest.mark.parametrize("short, other, near", [
    ("/odom", "/odmo", True),     # swapped neighbours
    ("/odom", "/odoom", True),    # doubled letter
    ("/dock", "/dok", True),      # dropped letter, three left
    ("/odom", "/odon", False),    # substitution: another word as often as a typo
    ("/left", "/lift", False),
    ("/map", "/mp", True),        # dropped letter, two left
    ("/a", "/ab", False),         # too short to tell
    ("/map", "/Map", True),       # case only
    ("/scan", "/scans", True),    # plural
])
def test_short_names_need_a_tighter_slip(short, other, near):
    g = graph(node("a", pub(short), sub("/ack"), path="a.py"), node("b", sub(other), pub("/ack"), path="b.py"))
    found = any("did you mean" in m for m in messages(g, select=["ROS001"]))
    assert found is near


def test_long_names_tolerate_two_edits_medium_names_one():
    assert token_typo("image_rectified", "imag_rectifed") == 2
    assert token_typo("battery", "batery") == 1
    assert token_typo("battery", "batry") is None


def test_services_and_actions_compare_with_every_server():
    g = graph(node("robot", srv("/reset_odom", type=TRIGGER), asrv("/fibonacci", type=FIB), path="robot.py"),
              node("ui", cli("/reset_odom", type=TRIGGER), cli("/rest_odom", type=TRIGGER),
                   acli("/fibonacci", type=FIB), acli("/Fibonacci", type=FIB), path="ui.py"))
    assert messages(g) == [
        "ROS008 service '/rest_odom' has no server; did you mean '/reset_odom' (served at robot.py:2)?",
        "ROS009 action '/Fibonacci' has no server; did you mean '/fibonacci' (served at robot.py:3)?",
    ]


def test_a_node_is_never_its_own_near_miss():
    g = graph(node("relay", sub("/scan"), pub("/scans"), sub("/ack"), path="relay.py"),
              node("x", pub("/ack"), path="x.py"))
    assert all("did you mean" not in m for m in messages(g))


def test_another_instance_of_the_same_code_node_is_not_its_near_miss():
    # one relay started by two launch files: two instances of one creation site
    first = node("relay", sub("/scan"), pub("/scans"), sub("/ack"), path="relay.py")
    second = node("relay", sub("/scan"), pub("/scans"), sub("/ack"), path="relay.py")
    assert all("did you mean" not in m for m in messages(graph(first, second, node("x", pub("/ack")))))


def test_the_transposition_distance_is_the_optimal_string_alignment():
    def reference(a, b):
        d = [[i + j if i * j == 0 else 0 for j in range(len(b) + 1)] for i in range(len(a) + 1)]
        for i in range(1, len(a) + 1):
            for j in range(1, len(b) + 1):
                d[i][j] = min(d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1]))
                if i > 1 and j > 1 and a[i - 1] == b[j - 2] and a[i - 2] == b[j - 1]:
                    d[i][j] = min(d[i][j], d[i - 2][j - 2] + 1)
        return d[-1][-1]

    rng = random.Random(7)
    for _ in range(3000):
        a = "".join(rng.choice("abc_") for _ in range(rng.randint(0, 8)))
        b = "".join(rng.choice("abc_") for _ in range(rng.randint(0, 8)))
        for limit in range(4):
            assert transposition_distance(a, b, limit) == min(reference(a, b), limit + 1), (a, b, limit)


def test_folding_and_families():
    assert folded("/Nav/Goal_Poses") & folded("/nav/goal_pose") == {"/nav/goal_pose"}
    assert folded("/battery_status") == {"/battery_status"}   # 'us', 'is', 'ss' are no plurals
    assert folded("/trajectories") == {"/trajectory"}
    assert folded("/statuses") & folded("/status") == {"/status"}
    assert folded("/boxes") & folded("/box") == {"/box"}
    assert folded("/passes") & folded("/pass") == {"/pass"}
    assert is_family("/robot1/odom", "/robot2/odom") and not is_family("/odom", "/odom_raw")
