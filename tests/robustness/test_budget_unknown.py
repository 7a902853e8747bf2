"""Budget exhaustion yields "unknown", never a partial set of names presented as complete.

A recursive helper builds topic names; a script's node subscribes to two of
them in a loop. Whatever the task budget — generous, or cut anywhere in the middle of
the recursion — the subscriptions' names are either the complete family or
unknown. A partial family would make ROS003 report the missing members'
publishers as absent, and change with unrelated files (which move the budget).
"""
from __future__ import annotations

from pathlib import Path

from flake8_rosgraph.absint.engine import Analysis
from flake8_rosgraph.absint.program import Program
from flake8_rosgraph.analysis import load_stubs
from flake8_rosgraph.graph.builder import build_graph_from
from flake8_rosgraph.workspace import load_workspace

BUILDER = '''\
import rclpy
from std_msgs.msg import String


def unit_topic(depth):
    if depth == 0:
        return '/fleet'
    return unit_topic(depth - 1) + '/unit' + str(depth)


def on_msg(msg):
    pass


rclpy.init()
node = rclpy.create_node('fleet')
for topic in (unit_topic(2), unit_topic(5)):
    node.create_subscription(String, topic, on_msg, 10)
'''

FULL = {"/fleet/unit1/unit2", "/fleet/unit1/unit2/unit3/unit4/unit5"}


def subscriptions(root: Path, budget: int | None) -> tuple[set[str | None], bool]:
    library, _ = load_stubs()
    analysis = Analysis(Program(load_workspace(root).modules), library, max_task_runs=budget)
    analysis.run()
    graph = build_graph_from(analysis)
    names = {e.name for n in graph.nodes if n.name in ("fleet", None) for e in n.entities if e.kind == "subscriptions"}
    return names, analysis.stopped or bool(analysis.abandoned)


def test_names_are_complete_or_unknown_at_every_budget(tmp_path: Path) -> None:
    (tmp_path / "fleet.py").write_text(BUILDER)
    names, exhausted = subscriptions(tmp_path, None)
    assert not exhausted and names == FULL, names
    cut_short = 0
    for budget in range(1, 60):
        names, exhausted = subscriptions(tmp_path, budget)
        if not exhausted:
            assert names == FULL, (budget, names)
            continue
        cut_short += 1
        assert names <= FULL | {None}, (budget, names)
        # Nothing (the constructor never ran), unknown, or all: never some names shown as all.
        assert not names or None in names or names == FULL, \
            f"budget {budget}: partial names {sorted(names)} shown as complete"
    assert cut_short > 3, "the budgets tried never cut the analysis short"
