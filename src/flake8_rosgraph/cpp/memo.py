"""The C++ partner ends as plain JSON, so that a run whose C++ sources did not change reuses them.

They depend only on the C++ sources and the package manifests: an edit to a Python file (the
common case for a Python linter) leaves them as they were, and reading C++ with tree-sitter is
a large part of a cold run on a mixed workspace. The round trip is exact (tuples stay tuples),
so the findings do not depend on whether the ends came from the disk.
"""
from __future__ import annotations

from dataclasses import fields
from typing import Any

from ..graph.model import Diagnostic, Entity, Location, RosNode

#: Version of the layout below.
MEMO_FORMAT = 1


def _plain(value: Any) -> Any:
    if isinstance(value, tuple):
        return {"tuple": [_plain(v) for v in value]}
    if isinstance(value, list):
        return [_plain(v) for v in value]
    if isinstance(value, dict):
        return {"dict": [[_plain(k), _plain(v)] for k, v in value.items()]}
    if isinstance(value, Location):
        return {"at": [value.path, value.line, value.column]}
    return value


def _typed(value: Any) -> Any:
    if isinstance(value, list):
        return [_typed(v) for v in value]
    if isinstance(value, dict):
        if "tuple" in value:
            return tuple(_typed(v) for v in value["tuple"])
        if "dict" in value:
            return {_typed(k): _typed(v) for k, v in value["dict"]}
        if "at" in value:
            return Location(*value["at"])
        raise ValueError("not a memo value")
    return value


def _record(item: Any) -> dict[str, Any]:
    return {f.name: _plain(getattr(item, f.name)) for f in fields(item)}


def to_obj(nodes: list[RosNode], diagnostics: list[Diagnostic]) -> dict[str, Any]:
    """``nodes`` (with their entities) and ``diagnostics`` as JSON-safe data."""
    return {"format": MEMO_FORMAT,
            "nodes": [dict(_record(node), entities=[_record(e) for e in node.entities]) for node in nodes],
            "diagnostics": [_record(d) for d in diagnostics]}


def from_obj(obj: Any) -> tuple[list[RosNode], list[Diagnostic]]:
    """What :func:`to_obj` wrote; ``ValueError``/``KeyError``/``TypeError`` if it is not that."""
    if not isinstance(obj, dict) or obj.get("format") != MEMO_FORMAT:
        raise ValueError("not a C++ memo")
    nodes = []
    for raw in obj["nodes"]:
        values = {name: _typed(value) for name, value in raw.items() if name != "entities"}
        values["entities"] = [Entity(**{k: _typed(v) for k, v in e.items()}) for e in raw["entities"]]
        nodes.append(RosNode(**values))
    return nodes, [Diagnostic(**{k: _typed(v) for k, v in d.items()}) for d in obj["diagnostics"]]
