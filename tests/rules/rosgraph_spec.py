"""Build small RosGraphs from a compact spec and run the rules on them (pyflakes-style test helper).

``node("talker", pub("/chatter"))`` is a node created at ``talker.py:1`` whose
entities sit on the following lines (``talker.py:2``, ...), unless an entity
gives its own ``line=`` (several entities on one line are alternatives of one
creation site). Types default to ``std_msgs/msg/String``.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Iterable

from flake8_rosgraph.graph.model import Entity, Location, RosGraph, RosNode
from flake8_rosgraph.rules import RuleConfig, run_rules
from flake8_rosgraph.rules.base import Finding

STRING = "std_msgs/msg/String"


@dataclass(frozen=True)
class Spec:
    kind: str
    name: str | None
    line: int | None = None
    fields: dict[str, Any] = field(default_factory=dict)


def _spec(kind: str):
    def make(name: str | None, type: str | None = STRING, line: int | None = None, **fields: Any) -> Spec:
        return Spec(kind, name, line, {"type": type, **fields})
    make.__name__ = kind
    return make


pub = _spec("publishers")
sub = _spec("subscriptions")
srv = _spec("services")
cli = _spec("clients")
asrv = _spec("action_servers")
acli = _spec("action_clients")


def node(name: str | None, *specs: Spec, namespace: str | None = "/", path: str | None = None,
         line: int = 1, **fields: Any) -> RosNode:
    path = path or f"{name or 'unknown'}.py"
    entities = []
    for offset, spec in enumerate(specs, start=line + 1):
        where = Location(path, spec.line or offset, 9)
        entities.append(Entity(spec.kind, spec.name, where, **spec.fields))
    return RosNode(name, namespace, Location(path, line, 9), entities=entities, **fields)


def graph(*nodes: RosNode) -> RosGraph:
    return RosGraph(nodes=list(nodes))


def findings(g: RosGraph, select: Iterable[str] | None = None, external: Iterable[str] = ()) -> list[Finding]:
    """The findings of the default rules (or of the ``select``-ed ones) on ``g``."""
    return run_rules(g, RuleConfig(external_names=frozenset(external)), select)


def report(g: RosGraph, **kw: Any) -> list[str]:
    """Findings as ``"ROS001 path:line"`` strings, the way flake8 would list them."""
    return [f"{f.code} {f.location.short()}" for f in findings(g, **kw)]


def codes(g: RosGraph, **kw: Any) -> list[str]:
    return [f.code for f in findings(g, **kw)]


def messages(g: RosGraph, **kw: Any) -> list[str]:
    return [f"{f.code} {f.message}" for f in findings(g, **kw)]
