"""The graph as JSON, per the public contract ``rosgraph/1`` (docs: graph-json.md).

Key order and list order are fixed, so the same graph always serialises to the
same bytes.  Extra keys (``conditional``, ``invalid``, ``via``, ``partial``, ``from_parameter``,
``name_template``, ``language``, ``diagnostics``) are additions the contract allows; consumers ignore what they do
not know.
"""
from __future__ import annotations

import json
from typing import Any

from ..escaping import json_safe
from .model import KINDS, Entity, RosGraph, RosNode

SCHEMA = "rosgraph/1"


def _entity(e: Entity) -> dict[str, Any]:
    out: dict[str, Any] = {}
    if e.kind in ("publishers", "subscriptions"):
        out["topic"] = e.name
    elif e.kind == "timers":
        out["period"] = e.period
    else:
        out["name"] = e.name
    if e.kind not in ("timers", "parameters"):
        out["type"] = e.type
    if e.kind in ("publishers", "subscriptions"):
        out["qos"] = e.qos if e.qos is not None else {}
    if e.kind in ("subscriptions", "services", "action_servers", "timers"):
        out["callback"] = e.callback
    if e.kind == "parameters":
        out["default"] = e.default
    out.update(path=e.location.path, line=e.location.line, column=e.location.column)
    if e.conditional:
        out["conditional"] = True
    if e.invalid:
        out["invalid"] = e.invalid
    if e.via:
        out["via"] = e.via
    if e.partial:
        out["partial"] = True
    if e.from_parameter is not None:
        out["from_parameter"] = e.from_parameter
    elif e.name_template is not None:
        out["name_template"] = [{"parameter": parameter, "default": text} if parameter else text
                                for parameter, text in e.name_template]
    return out


def _node(n: RosNode) -> dict[str, Any]:
    out: dict[str, Any] = {
        "name": n.name, "namespace": n.namespace, "fqn": n.fqn,
        "path": n.location.path, "line": n.location.line, "column": n.location.column,
        "class": n.cls,
    }
    for kind in KINDS:
        out[kind] = [_entity(e) for e in n.entities if e.kind == kind]
    if n.conditional:
        out["conditional"] = True
    if n.invalid:
        out["invalid"] = n.invalid
    if n.language != "python":
        out["language"] = n.language
    if n.unresolved_base:
        out["unresolved_base"] = n.unresolved_base
    if n.passed_in:
        out["passed_in"] = n.passed_in
    return out


def to_json_obj(graph: RosGraph) -> dict[str, Any]:
    return {
        "schema": SCHEMA,
        "nodes": [_node(n) for n in graph.nodes],
        "diagnostics": [{"path": d.path, "line": d.line, "severity": d.severity,
                         "message": d.message} for d in sorted(graph.diagnostics)],
    }


def to_json(graph: RosGraph) -> str:
    return json_safe(json.dumps(to_json_obj(graph), indent=1, ensure_ascii=False)) + "\n"
