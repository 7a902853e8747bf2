"""The rule registry: order, lookup, selection, sorted and deduplicated output, determinism."""
import random

import pytest
from rosgraph_spec import codes, findings, graph, node, pub, sub

from flake8_rosgraph.graph.model import Location, RosGraph
from flake8_rosgraph.rules import RULES, RuleConfig, rule_by_code, run_rules
from flake8_rosgraph.rules.base import Finding, Rule
from flake8_rosgraph.rules.docs import SECTIONS, rule_doc

EXPECTED_CODES = ([f"ROS{n:03d}" for n in range(1, 11)] + [f"ROS{n:03d}" for n in range(101, 108)]
                  + [f"ROS{n:03d}" for n in range(201, 207)])


def test_rules_in_code_order_one_per_code():
    assert [rule.code for rule in RULES] == EXPECTED_CODES


def test_rule_attributes():
    for rule in RULES:
        assert rule.level in {"error", "warning", "note"}
        assert rule.name and rule.name == rule.name.lower() and " " not in rule.name
        assert rule.summary
        assert rule.precision in {"very-high", "high", "medium", "low"}  # SARIF / GitHub code scanning values
    assert [rule.code for rule in RULES if not rule.default_enabled] == ["ROS010"]


@pytest.mark.parametrize("rule", RULES, ids=lambda r: r.code)
def test_docstring_has_the_ruff_sections(rule):
    doc = rule_doc(rule)
    assert tuple(title for title, _ in doc.sections) == SECTIONS
    assert all(body for _, body in doc.sections)


@pytest.mark.parametrize("rule", RULES, ids=lambda r: r.code)
def test_each_rule_lives_in_its_own_module(rule):
    assert type(rule).__module__.split(".")[-1].startswith(rule.code.lower() + "_" + rule.name.replace("-", "_"))


def test_rule_by_code():
    assert rule_by_code("ROS004").name == "message-type-mismatch"
    with pytest.raises(KeyError):
        rule_by_code("ROS999")


def mixed():
    return graph(node("a", pub("/x"), sub("/x"), pub("/orphan")), node("b", sub("/x")),
                 node("c", sub(None)), node("d", pub(None, type="std_msgs/msg/Int32")))


def test_select_none_runs_the_default_rules():
    assert codes(mixed()) == ["ROS002"]


def test_select_exact_codes_and_prefixes():
    assert codes(mixed(), select=["ROS010"]) == ["ROS010", "ROS010"]
    assert codes(mixed(), select=["ROS00"]) == ["ROS002"]
    assert codes(mixed(), select=["ROS"]) == ["ROS002", "ROS010", "ROS010"]
    assert codes(mixed(), select=[]) == []


class Twice(Rule):
    """A rule that reports the same finding twice, out of order."""

    code, name, level, summary = "ROS999", "twice", "note", "test"

    def check(self, graph: RosGraph, config: RuleConfig):
        late = Finding(Location("b.py", 2, 1), self.code, "late")
        early = Finding(Location("a.py", 9, 1), self.code, "early")
        yield from (late, early, late)


def test_run_rules_sorts_and_deduplicates(monkeypatch):
    monkeypatch.setattr("flake8_rosgraph.rules.RULES", (Twice(),))
    result = run_rules(RosGraph(), RuleConfig(), select=["ROS999"])
    assert [f.message for f in result] == ["early", "late"]


def test_same_graph_in_another_order_gives_identical_findings():
    nodes = [node(f"n{i}", pub(f"/t{i}"), sub(f"/t{(i + 1) % 7}"), pub("/dbg"), sub("/t0", line=40),
                  pub("/cmd_vel" if i == 3 else "/cmdvel_" + str(i)), sub("/cmdvel"))
             for i in range(7)]
    expected = findings(graph(*nodes), select=["ROS"])
    assert expected
    for seed in range(5):
        shuffled = nodes[:]
        random.Random(seed).shuffle(shuffled)
        for n in shuffled:
            random.Random(seed).shuffle(n.entities)
        assert findings(graph(*shuffled), select=["ROS"]) == expected
