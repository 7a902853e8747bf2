"""The near-miss hint: a dangling end whose likely partner is dangling too, under a slightly different name.

A publisher on ``/cmd_vel`` with no subscriber *and* a subscription on
``/cmdvel`` with no publisher is the strongest signal the wiring rules have: it
is almost always a typo or a namespace slip, not an interface. Two names are
near misses when, with compatible message types,

* they are within a small edit distance (1 for names shorter than
  :data:`LONG_NAME` characters, 2 otherwise, 1 again past
  :data:`MAX_DISTANCE_2_NAME`; none past :data:`MAX_HINTED_NAME`), or
* they differ only by namespace: the same last component
  (``/robot1/scan`` vs ``/scan``; a forgotten or extra leading ``/`` in code
  shows up this way once names are resolved);

but not when they differ only in their numbers (``/topic5`` vs ``/topic8``,
``/robot1/odom`` vs ``/robot2/odom``): numbered names are deliberate families.
"""
from __future__ import annotations

import re
from collections import defaultdict
from dataclasses import dataclass
from typing import Sequence

from ..graph.names import edit_distance
from .topics import Endpoint, types_compatible

#: Names at least this long tolerate an edit distance of 2 instead of 1.
LONG_NAME = 10
#: The largest edit distance any lookup tolerates (that of long names).
MAX_DISTANCE = 2
#: The deletion index grows with the cube of a name's length at distance 2 (400 names of a
#: few hundred characters took a minute and gigabytes): names longer than this are matched
#: at distance 1 only, and names longer than :data:`MAX_HINTED_NAME` (which rcl rejects) get no hint.
MAX_DISTANCE_2_NAME = 64
MAX_HINTED_NAME = 256

_NUMBER = re.compile(r"\d+")


def _basename(name: str) -> str:
    return name.rsplit("/", 1)[-1]


def _deletions(word: str, depth: int) -> set[str]:
    """``word`` and every string made from it by deleting up to ``depth`` characters.

    Two strings within Levenshtein distance *k* always share such a variant
    with at most *k* deletions on each side (delete the substituted and the
    inserted characters), so matching variants finds every candidate without
    comparing all pairs of names.
    """
    variants = {word}
    frontier = {word}
    for _ in range(depth):
        frontier = {w[:i] + w[i + 1:] for w in frontier for i in range(len(w))}
        variants |= frontier
    return variants


def _depth(name: str) -> int:
    """The edit distance indexed and tolerated for ``name`` (see :data:`MAX_DISTANCE_2_NAME`)."""
    return MAX_DISTANCE if len(name) <= MAX_DISTANCE_2_NAME else 1


@dataclass(frozen=True)
class NearMiss:
    """The dangling peer name a dangling end probably meant, and where that peer is."""

    name: str
    peer: Endpoint


class NearMissFinder:
    """Looks up near misses among the dangling peers of one kind.

    Built once per rule run from the dangling peer names (indexed by their
    deletion variants and by their last component), so a lookup touches only
    plausible candidates, never every dangling name of the workspace.
    """

    def __init__(self, dangling_peers: dict[str, Sequence[Endpoint]]) -> None:
        self._peers = dangling_peers
        self._by_variant: dict[str, set[str]] = defaultdict(set)
        self._by_basename: dict[str, list[str]] = defaultdict(list)
        for name in sorted(n for n in dangling_peers if len(n) <= MAX_HINTED_NAME):
            for variant in _deletions(name, _depth(name)):
                self._by_variant[variant].add(name)
            self._by_basename[_basename(name)].append(name)

    def find(self, endpoint: Endpoint) -> NearMiss | None:
        """The best near miss for ``endpoint`` (closest name first, then alphabetical), if any."""
        name = endpoint.entity.name
        if name is None or len(name) > MAX_HINTED_NAME:
            return None
        limit = 1 if len(name) < LONG_NAME else _depth(name)
        candidates: dict[str, int] = {}
        for variant in _deletions(name, limit):
            for other in self._by_variant.get(variant, ()):
                if other not in candidates:
                    distance = edit_distance(name, other, limit)
                    if distance <= limit:
                        candidates[other] = distance
        for other in self._by_basename.get(_basename(name), ()):
            candidates.setdefault(other, edit_distance(name, other, len(name) + len(other)))
        ranked = sorted((distance, other) for other, distance in candidates.items()
                        if self._plausible(name, other))
        for _, other in ranked:
            compatible = [p for p in self._peers[other] if types_compatible(endpoint.entity.type, p.entity.type)]
            if compatible:
                return NearMiss(other, compatible[0])
        return None

    @staticmethod
    def _plausible(name: str, other: str) -> bool:
        return _NUMBER.sub("#", name) != _NUMBER.sub("#", other)
