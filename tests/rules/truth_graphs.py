"""Load graph JSON (``rosgraph/1``, see docs/graph-json.md) into the model, for calibration on real repositories.

The dev evaluation kit ships hand-checked ground-truth graphs of ros2/examples
and ros2/demos next to this repository (``../shared/eval/truth``); running the
rules on them measures their noise on real code without needing the extractor.
"""
from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from flake8_rosgraph.graph.model import KINDS, Entity, Location, RosGraph, RosNode

TRUTH_DIR = Path(__file__).resolve().parents[3] / "shared" / "eval" / "truth"

_NAME_KEY = {"publishers": "topic", "subscriptions": "topic"}


def _location(obj: dict[str, Any]) -> Location:
    return Location(obj["path"], obj["line"], obj.get("column", 1))


def _entity(kind: str, obj: dict[str, Any]) -> Entity:
    return Entity(
        kind=kind,
        name=obj.get(_NAME_KEY.get(kind, "name")) if kind != "timers" else None,
        location=_location(obj),
        type=obj.get("type"),
        qos=obj.get("qos"),
        callback=obj.get("callback"),
        period=obj.get("period"),
        default=obj.get("default"),
        conditional=bool(obj.get("conditional", False)),
        via=obj.get("via"),
    )


def load_graph(path: Path) -> RosGraph:
    data = json.loads(path.read_text(encoding="utf-8"))
    nodes = []
    for obj in data["nodes"]:
        entities = [_entity(kind, e) for kind in KINDS for e in obj.get(kind, [])]
        nodes.append(RosNode(obj["name"], obj["namespace"], _location(obj), cls=obj.get("class"),
                             conditional=bool(obj.get("conditional", False)), entities=entities))
    return RosGraph(nodes=nodes)
