"""The nodes as written in code: the deployment ``ros2 run`` gives, beside the launched one.

The rules judge the graph as the workspace's launch files start it
(:func:`~flake8_rosgraph.launch.api.judged_graph`): a launched node is replaced by its
launched copies, renamed, put in a namespace and remapped. But every executable also runs as
written (``ros2 run``, a test, a launch file of another workspace), under the names its code
gives. Two programs whose code clashes there — one node name for two programs that talk, a
subscription whose QoS its publisher cannot offer — still clash, though the launch files
happen to start them apart. The rules that judge a *pair* (never an absence: a launch remap
may be exactly what connects an end) also judge this graph, for what the launched one hides.
"""
from __future__ import annotations

from collections import defaultdict
from typing import Callable, Iterable, Iterator

from ..graph.model import RosGraph, RosNode
from .base import Finding, RuleConfig
from .shared import once


def written_graph(graph: RosGraph) -> RosGraph | None:
    """Every node of the (judged) ``graph`` under the name its code gives it, or ``None`` when no
    launch file starts a node (then the judged graph is the written one)."""
    return once("written", graph, lambda: _written(graph))


def _written(graph: RosGraph) -> RosGraph | None:
    codes = [instance.code for system in graph.systems for instance in system.instances]
    if not codes:
        return None
    nodes: dict[int, RosNode] = {}
    for node in (*(n for n in graph.nodes if n.launch is None), *codes):
        nodes.setdefault(id(node), node)
    return RosGraph(sorted(nodes.values(), key=lambda n: (n.fqn or "", n.location)))


def launched_names(graph: RosGraph) -> dict[int, frozenset[str | None]]:
    """The fully qualified names each node's code runs under, by ``id()`` of the code node: the
    names its launch actions give it (``None`` where a launch file makes the name unknown);
    a node no launch file starts is absent (it runs under its written name)."""
    def build() -> dict[int, frozenset[str | None]]:
        names: dict[int, set[str | None]] = defaultdict(set)
        for system in graph.systems:
            for instance in system.instances:
                names[id(instance.code)].add(instance.node.fqn)
        return {key: frozenset(found) for key, found in names.items()}
    return once("launched-names", graph, build)


def also_as_written(check: Callable[[RosGraph, RuleConfig], Iterable[Finding]], graph: RosGraph,
                    config: RuleConfig, note: str) -> Iterator[Finding]:
    """``check``'s findings on the judged ``graph``, then those on the nodes as written at places
    the first pass does not report, each with ``note`` (why the launched system hides it)."""
    reported = list(check(graph, config))
    yield from reported
    written = written_graph(graph)
    if written is None:
        return
    seen = {finding.location for finding in reported}
    for finding in check(written, config):
        if finding.location not in seen:
            yield Finding(finding.location, finding.code, finding.message + note, finding.related)
