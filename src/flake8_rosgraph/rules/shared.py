"""What several rules compute from the same graph, computed once while :func:`run_rules` runs.

The four absence rules (ROS001/003/008/009), ROS004, ROS005 and ROS007 each index the
graph's ends by name, and the absence rules each look up which launch systems started which
nodes and which names unseen code may use. On a large workspace that repeated work was a
third of the rules' time, and the rules run again on every edit (pre-commit, an editor).

The memo lives only inside :func:`shared_indexes` (``run_rules`` opens it), keyed by what is
indexed and the graph object's identity, and holding the graph so that identity cannot be
reused meanwhile. A rule run on its own (a test calling ``rule.check``) builds its indexes
itself, as before: nothing can be stale across graphs or after a graph is changed.
"""
from __future__ import annotations

import contextlib
from typing import Any, Callable, Iterator, TypeVar

from ..graph.model import RosGraph

T = TypeVar("T")

_ACTIVE: dict[tuple[str, int], tuple[RosGraph, Any]] | None = None


@contextlib.contextmanager
def shared_indexes() -> Iterator[None]:
    """Share the indexes of each graph between the rules run inside the block."""
    global _ACTIVE
    outer, _ACTIVE = _ACTIVE, {}
    try:
        yield
    finally:
        _ACTIVE = outer


def once(what: str, graph: RosGraph, build: Callable[[], T]) -> T:
    """``build()``, or what it gave for ``what`` of this ``graph`` earlier in the same block."""
    if _ACTIVE is None:
        return build()
    key = (what, id(graph))
    if key not in _ACTIVE:
        _ACTIVE[key] = (graph, build())
    return _ACTIVE[key][1]
