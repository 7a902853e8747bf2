"""ROS005 qos-incompatible: the rmw_dds_common error cases, and nothing when a policy is unknown."""
import pytest
from rosgraph_spec import codes, findings, graph, messages, node, pub, sub

from flake8_rosgraph.graph.model import Location


def pair(pub_qos, sub_qos):
    return graph(node("talker", pub("/chatter", qos=pub_qos)), node("listener", sub("/chatter", qos=sub_qos)))


INCOMPATIBLE = [
    ({"reliability": "best_effort"}, {"reliability": "reliable"}, "best-effort publisher, reliable subscription"),
    ({"durability": "volatile"}, {"durability": "transient_local"},
     "volatile publisher, transient-local subscription"),
    ({"deadline": 0.0}, {"deadline": 1.0}, "subscription has a deadline (1s) but publisher has none"),
    ({"deadline": 2.0}, {"deadline": 0.5}, "subscription deadline 0.5s is shorter than publisher's 2s"),
    ({"liveliness": "automatic"}, {"liveliness": "manual_by_topic"},
     "automatic-liveliness publisher, manual-by-topic subscription"),
    ({"liveliness_lease_duration": 0}, {"liveliness_lease_duration": 3},
     "subscription has a liveliness lease duration (3s) but publisher has none"),
    ({"liveliness_lease_duration": 5.0}, {"liveliness_lease_duration": 3.0},
     "subscription liveliness lease duration 3s is shorter than publisher's 5s"),
]

COMPATIBLE = [
    ({"reliability": "reliable"}, {"reliability": "best_effort"}),
    ({"reliability": "best_effort"}, {"reliability": "best_effort"}),
    ({"reliability": "system_default"}, {"reliability": "reliable"}),   # only a warning in rmw
    ({"durability": "transient_local"}, {"durability": "volatile"}),
    ({"durability": "transient_local"}, {"durability": "transient_local"}),
    ({"deadline": 1.0}, {"deadline": 0.0}),
    ({"deadline": 0.5}, {"deadline": 2.0}),
    ({"deadline": 1.0}, {"deadline": 1.0}),
    ({"liveliness": "manual_by_topic"}, {"liveliness": "automatic"}),
    ({"liveliness_lease_duration": 1.0}, {"liveliness_lease_duration": 3.0}),
    # A policy missing on either side is unknown (or default): never compared.
    ({"depth": 10}, {"depth": 10, "reliability": "reliable", "durability": "transient_local"}),
    ({"depth": 5, "reliability": "best_effort", "durability": "volatile"}, {"depth": 10}),
    ({}, {"deadline": 1.0}),
    (None, {"reliability": "reliable"}),
    ({"deadline": "unknown"}, {"deadline": 1.0}),
]


@pytest.mark.parametrize(("pub_qos", "sub_qos", "reason"), INCOMPATIBLE)
def test_incompatible(pub_qos, sub_qos, reason):
    assert messages(pair(pub_qos, sub_qos)) == [
        f"ROS005 QoS of subscription to '/chatter' cannot match the publisher at talker.py:2: {reason}"]


@pytest.mark.parametrize(("pub_qos", "sub_qos"), COMPATIBLE)
def test_compatible_or_unknown(pub_qos, sub_qos):
    assert codes(pair(pub_qos, sub_qos)) == []


def test_all_reasons_of_one_pair_in_one_finding_at_the_subscription():
    g = pair({"reliability": "best_effort", "durability": "volatile", "profile": "sensor_data"},
             {"reliability": "reliable", "durability": "transient_local"})
    (finding,) = findings(g)
    assert finding.location == Location("listener.py", 2, 9)
    assert finding.related == ((Location("talker.py", 2, 9), "publisher '/chatter'"),)
    assert finding.message.endswith(
        "best-effort publisher, reliable subscription; volatile publisher, transient-local subscription")


def test_one_finding_per_incompatible_publisher():
    g = graph(node("a", pub("/chatter", qos={"reliability": "best_effort"})),
              node("b", pub("/chatter", qos={"reliability": "reliable"})),
              node("c", pub("/chatter", qos={"reliability": "best_effort"})),
              node("listener", sub("/chatter", qos={"reliability": "reliable"})))
    assert [f.related[0][0].path for f in findings(g)] == ["a.py", "c.py"]


def test_other_topics_are_not_paired():
    g = graph(node("a", pub("/x", qos={"reliability": "best_effort"}), sub("/y", qos={"depth": 1})),
              node("b", sub("/y", qos={"reliability": "reliable"}), pub("/y", qos={"depth": 1}),
                   sub("/x", qos={"reliability": "best_effort"})))
    assert codes(g, select=["ROS005"]) == []
