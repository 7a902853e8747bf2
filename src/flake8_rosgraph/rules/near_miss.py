"""The near-miss hint: the name a dangling end probably meant, among every name of the other role.

A typo usually hits a name that other nodes still use correctly (a second
listener on ``/chatter`` misspelt ``/chater``), so the partner it meant is
*connected*, not dangling: every name used in the other role is a candidate,
whatever its state. Two names are near misses, with compatible message types,
when they are the same name

* resolved differently: the written name of the dangling end, taken as
  private (``~/x``), relative (``x``) or absolute (``/x``) in its node, gives
  the other name;
* with one namespace token dropped or added (``/robot/scan`` vs ``/scan``), or one
  ``_``-separated word dropped or added at either end of a namespace token
  (``/qr_detection/delta`` vs ``/qr_detection_pkg/delta``: a package's namespace written
  without its suffix);
* up to case and the plural of the last word (``/Scan``, ``/goal_poses``);
* with one token misspelt (edit distance with transpositions): for a token of
  at most :data:`SHORT_TOKEN` characters only a swap of two neighbours or one
  character more or less (``/odmo``, ``/odoom``, ``/dok``; a substitution in a
  short word is as often another word: ``/left``, ``/lift``), one edit up to
  :data:`LONG_TOKEN` characters, two beyond;

but never when they differ only in their numbers (``/topic5`` vs ``/topic8``,
``/robot1/odom`` vs ``/robot2/odom``, ``/cmd`` vs ``/cmd2``): numbered names
are deliberate families.

The index holds, per peer name, a bounded number of keys (its folded forms,
its names with one token dropped, and per token its deletion variants, depth
two only for tokens of at most :data:`DEEP_TOKEN` characters), so building it
and looking a name up stay linear in the total length of the names.
"""
from __future__ import annotations

import re
from collections import defaultdict
from dataclasses import dataclass
from functools import lru_cache
from typing import Callable, Iterable, Sequence

from ..graph.model import RosNode
from .topics import Endpoint, types_compatible

#: Tokens of at most this many characters accept only a transposition or one character more or less.
SHORT_TOKEN = 5
#: ... and only when both keep at least this many characters (``/a`` and ``/ab`` are just different).
MIN_TOKEN = 2
#: Tokens shorter than this accept one edit; longer ones two.
LONG_TOKEN = 10
#: Tokens longer than this are indexed with single deletions only (two-edit typos there go unseen).
DEEP_TOKEN = 24

_NUMBER = re.compile(r"\d+")
#: Plural endings and what the singular may end with instead (``poses``: ``pose``; ``statuses``: ``status``).
_PLURAL = (("ies", ("y",)), ("es", ("e", "")), ("s", ("",)))
#: Endings of singular words that look plural (``status``, ``axis``, ``pass``).
_NOT_PLURAL = ("ss", "us", "is")

#: Kinds of near miss, best first: a resolution slip is an exact fact; a typo beats a leaf shared across namespaces.
RESOLUTION, FOLDED, SPELLING, NAMESPACE_TOKEN = range(4)


def _tokens(name: str) -> list[str]:
    return [t for t in name.split("/") if t]


def _join(tokens: Sequence[str]) -> str:
    return "/" + "/".join(tokens)


def _singulars(word: str) -> set[str]:
    """``word`` if it is no plural, else what its singular may be (``boxes``: ``boxe`` or ``box``)."""
    if word.endswith(_NOT_PLURAL):
        return {word}
    for suffix, replacements in _PLURAL:
        if word.endswith(suffix) and len(word) > len(suffix) + 1:
            return {word[: -len(suffix)] + r for r in replacements}
    return {word}


def folded(name: str) -> set[str]:
    """``name`` in lower case with the last word of its last token in the singular (each way it may be)."""
    head, _, last = name.lower().rpartition("/")
    *words, word = last.split("_")
    return {f"{head}/{'_'.join([*words, singular])}" for singular in _singulars(word)}


def _word_keys(tokens: Sequence[str], shortened: bool) -> Iterable[tuple]:
    """Keys of a name under its namespace tokens, one key per namespace token: that token as
    it is or (``shortened``) without its first or last ``_``-separated word, with the position
    and the other tokens. Two names sharing a key differ in one namespace token by one word."""
    for i, token in enumerate(tokens[:-1]):
        context = (i, tuple(tokens[:i]), tuple(tokens[i + 1:]))
        words = token.split("_")
        if not shortened:
            yield (*context, token)
        elif len(words) > 1 and all(words):
            yield (*context, "_".join(words[1:]))
            yield (*context, "_".join(words[:-1]))


def _without_one_token(tokens: Sequence[str]) -> Iterable[str]:
    if len(tokens) > 1:
        for i in range(len(tokens)):
            yield _join([*tokens[:i], *tokens[i + 1:]])


@lru_cache(maxsize=65536)
def _deletions(word: str, depth: int) -> frozenset[str]:
    """``word`` and every string made from it by deleting up to ``depth`` characters
    (kept per word: the same tokens recur across names and across the four absence rules).

    Two strings within *k* edits (with transpositions) always share such a
    variant with at most *k* deletions on each side, so matching variants
    finds every candidate without comparing all pairs of names.
    """
    variants = {word}
    frontier = {word}
    for _ in range(depth):
        frontier = {w[:i] + w[i + 1:] for w in frontier for i in range(len(w))}
        variants |= frontier
    return frozenset(variants)


def _depth(token: str) -> int:
    return 2 if LONG_TOKEN <= len(token) <= DEEP_TOKEN else 1


def _spelling_keys(tokens: Sequence[str]) -> Iterable[int]:
    """Hashed (token position, the other tokens, deletion variant of the token) keys of a name."""
    for i, token in enumerate(tokens):
        context = hash((i, len(tokens), tuple(tokens[:i]), tuple(tokens[i + 1:])))
        for variant in _deletions(token, _depth(token)):
            yield hash((context, variant))


def transposition_distance(a: str, b: str, limit: int) -> int:
    """Edit distance counting a swap of neighbours as one edit (optimal string alignment), capped at ``limit + 1``.

    Only the diagonal band of width ``limit`` is computed: cells farther from
    it need more than ``limit`` insertions or deletions, so a comparison costs
    ``O(len * limit)`` however long the names are.
    """
    if a == b:
        return 0
    if abs(len(a) - len(b)) > limit:
        return limit + 1
    over = limit + 1
    before: dict[int, int] = {}
    previous = {j: j for j in range(min(len(b), limit) + 1)}
    for i in range(1, len(a) + 1):
        current = {0: i} if i <= limit else {}
        for j in range(max(1, i - limit), min(len(b), i + limit) + 1):
            best = min(previous.get(j, over) + 1, current.get(j - 1, over) + 1,
                       previous.get(j - 1, over) + (a[i - 1] != b[j - 1]))
            if i > 1 and j > 1 and a[i - 1] == b[j - 2] and a[i - 2] == b[j - 1]:
                best = min(best, before.get(j - 2, over) + 1)
            current[j] = best
        if min(current.values(), default=over) > limit:
            return over
        before, previous = previous, current
    return min(previous.get(len(b), over), over)


def token_typo(a: str, b: str) -> int | None:
    """The edit distance between two tokens if one is a plausible misspelling of the other, else ``None``."""
    if max(len(a), len(b)) <= SHORT_TOKEN:
        if transposition_distance(a, b, 1) != 1:
            return None
        swapped = len(a) == len(b) and sorted(a) == sorted(b)
        dropped = len(a) != len(b) and min(len(a), len(b)) >= MIN_TOKEN
        return 1 if swapped or dropped else None
    limit = 1 if min(len(a), len(b)) < LONG_TOKEN else 2
    distance = transposition_distance(a, b, limit)
    return distance if 0 < distance <= limit else None


def resolutions(endpoint: Endpoint) -> set[str]:
    """The names the endpoint's written name would have as private, relative or absolute name in its node."""
    raw = endpoint.entity.raw_name
    node: RosNode = endpoint.node
    if not raw or node.name is None or node.namespace is None or "{" in raw:
        return set()
    base = raw[2:] if raw.startswith("~/") else raw.lstrip("/~")
    if not base:
        return set()
    namespace = node.namespace.rstrip("/")
    return {f"{namespace}/{node.name}/{base}", f"{namespace}/{base}", f"/{base}"}


def is_family(a: str, b: str) -> bool:
    """Names that differ only in their numbers: a deliberate family, never a typo."""
    return _NUMBER.sub("", a) == _NUMBER.sub("", b)


@dataclass(frozen=True)
class NearMiss:
    """The peer name a dangling end probably meant, and where that peer is."""

    name: str
    peer: Endpoint
    #: How sure: :data:`RESOLUTION`, :data:`FOLDED`, :data:`SPELLING` or :data:`NAMESPACE_TOKEN`.
    kind: int = SPELLING

    def is_slip_of(self, endpoint: Endpoint) -> bool:
        """Whether ``endpoint``'s name is a slip of the pen for this one (resolution, case or
        plural, spelling — not a leaf shared across namespaces) with the same known message
        type: the surest sign of a typo, which an unknown elsewhere hardly explains."""
        own = endpoint.entity.type
        return self.kind != NAMESPACE_TOKEN and own is not None and own == self.peer.entity.type \
            and not self.peer.entity.partial  # a partly known end makes no end reportable


class NearMissFinder:
    """Looks up near misses among every name used by the peer kind.

    Built once per rule run; a lookup touches only the names sharing one of
    its keys, never every name of the workspace.
    """

    def __init__(self, peers: dict[str, Sequence[Endpoint]]) -> None:
        self._peers = peers
        self._folded: dict[str, list[str]] = defaultdict(list)
        self._one_token_more: dict[str, list[str]] = defaultdict(list)
        self._one_word_more: dict[tuple, list[str]] = defaultdict(list)
        self._one_word_less: dict[tuple, list[str]] = defaultdict(list)
        self._spelling: dict[int, list[str]] = defaultdict(list)
        for name in sorted(peers):
            tokens = _tokens(name)
            for key in folded(name):
                self._folded[key].append(name)
            for shorter in _without_one_token(tokens):
                self._one_token_more[shorter].append(name)
            for key in _word_keys(tokens, shortened=True):
                self._one_word_more[key].append(name)
            for key in _word_keys(tokens, shortened=False):
                self._one_word_less[key].append(name)
            for key in set(_spelling_keys(tokens)):
                self._spelling[key].append(name)

    def candidates(self, endpoint: Endpoint) -> dict[str, tuple[int, int]]:
        """Peer names near ``endpoint``'s name, each with its (kind of near miss, distance)."""
        name = endpoint.entity.name
        if name is None:
            return {}
        tokens = _tokens(name)
        found: dict[str, tuple[int, int]] = {}

        def add(other: str, rank: tuple[int, int]) -> None:
            if other != name and other in self._peers and not is_family(name, other):
                found[other] = min(found.get(other, rank), rank)

        for other in resolutions(endpoint):
            add(other, (RESOLUTION, abs(len(_tokens(other)) - len(tokens))))
        for key in folded(name):
            for other in self._folded.get(key, ()):
                add(other, (FOLDED, 0))
        for other in self._one_token_more.get(name, ()):
            add(other, (NAMESPACE_TOKEN, 1))
        for shorter in _without_one_token(tokens):
            add(shorter, (NAMESPACE_TOKEN, 1))
        for key in _word_keys(tokens, shortened=False):
            for other in self._one_word_more.get(key, ()):
                add(other, (NAMESPACE_TOKEN, 1))
        for key in _word_keys(tokens, shortened=True):
            for other in self._one_word_less.get(key, ()):
                add(other, (NAMESPACE_TOKEN, 1))
        seen: set[str] = set()
        for key in set(_spelling_keys(tokens)):
            for other in self._spelling.get(key, ()):
                if other not in seen:
                    seen.add(other)
                    distance = self.spelling_distance(tokens, _tokens(other))
                    if distance is not None:
                        add(other, (SPELLING, distance))
        return found

    @staticmethod
    def spelling_distance(tokens: list[str], others: list[str]) -> int | None:
        """How far apart two names of as many tokens are when exactly one token is misspelt, else ``None``."""
        if len(tokens) != len(others):
            return None
        differing = [(a, b) for a, b in zip(tokens, others) if a != b]
        return token_typo(*differing[0]) if len(differing) == 1 else None

    def find(self, endpoint: Endpoint, accept: Callable[[Endpoint], bool] | None = None) -> NearMiss | None:
        """The best near miss for ``endpoint`` (surest kind, then closest, then alphabetical), if any.

        ``accept``: which partners may be taken (those of one launch system, say),
        when a name has users in several systems. The partner must also be able
        to run with the endpoint (:meth:`Endpoint.sees`), sit on another node
        (not another instance of the same code node, as two launch files make
        it, unless another executable runs it: front ends of one driver class
        each add their own ends), and have a type that does not rule the match out. A
        misspelling (characters, case, plural) is also found in another test module of the
        endpoint's scope, and for a test fixture in any production end (:meth:`Endpoint.spells_for`):
        those never run with the endpoint, but they spell the name the endpoint means; how a
        name resolves, and its namespace tokens, belong to the nodes of one run.
        """
        ranked = sorted((rank, other) for other, rank in self.candidates(endpoint).items())
        for (kind, _), other in ranked:
            for peer in self._peers[other]:
                if (_other_program(peer.node, endpoint.node)
                        and (endpoint.sees(peer) or (kind in (FOLDED, SPELLING) and endpoint.spells_for(peer)))
                        and types_compatible(endpoint.entity.type, peer.entity.type)
                        and (accept is None or accept(peer))):
                    return NearMiss(other, peer, kind)
        return None


def _other_program(a: RosNode, b: RosNode) -> bool:
    """Whether two nodes are different programs: other code, or one node class run by two executables."""
    if a.location != b.location:
        return True
    return a.launch is not None and b.launch is not None and (
        (a.launch["package"], a.launch["executable"]) != (b.launch["package"], b.launch["executable"]))
