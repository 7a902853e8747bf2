"""An index of the graph's named endpoints, built in one pass, that the wiring rules query.

Every wiring rule asks the same questions — "who else uses this name with the
other role?", "could an entity whose name we could not resolve be that other
end?", "does this node talk to anybody?" — and answering them by rescanning
the graph per entity would make the rules quadratic in the workspace size.
"""
from __future__ import annotations

from collections import Counter, defaultdict
from dataclasses import dataclass, field

from ..graph.model import NAMED_KINDS, PEER_KIND, Entity, RosGraph, RosNode
from .exempt import ExemptNames


@dataclass(frozen=True)
class Endpoint:
    """An entity together with the node that creates it (the model's entities do not point back)."""

    node: RosNode
    entity: Entity

    @property
    def sort_key(self) -> tuple:
        return (self.entity.location, self.entity.kind, self.entity.name or "")


def namespace_of(name: str) -> str:
    """The namespace a resolved name lives in (``/a/b/c`` -> ``/a/b``, ``/c`` -> ``/``)."""
    return name.rsplit("/", 1)[0] or "/"


def _node_key(node: RosNode) -> str | int:
    """A node's identity across creation sites: its FQN, or the object itself when the name is unknown.

    Alternative versions of one node in several files (``minimal_publisher``
    in three styles) are one node, not several independent users of a name.
    """
    return node.fqn if node.fqn is not None else id(node)


def types_compatible(a: str | None, b: str | None) -> bool:
    """Unknown types never rule a match out; known ones must be equal."""
    return a is None or b is None or a == b


@dataclass
class EndpointIndex:
    """Named endpoints by (kind, resolved name), plus what is known of the unresolved ones."""

    by_name: dict[tuple[str, str], list[Endpoint]] = field(default_factory=dict)
    #: How many distinct nodes use each (kind, name); nodes of one fully qualified name count once.
    node_counts: dict[tuple[str, str], int] = field(default_factory=dict)
    #: The message types (``None`` = unknown) of the unresolved endpoints, by kind.
    unresolved_types: dict[str, frozenset[str | None]] = field(default_factory=dict)

    @classmethod
    def build(cls, graph: RosGraph) -> EndpointIndex:
        by_name: dict[tuple[str, str], list[Endpoint]] = defaultdict(list)
        unresolved_types: dict[str, set[str | None]] = defaultdict(set)
        for node, entity in graph.entities():
            if entity.kind not in NAMED_KINDS:
                continue
            if entity.name is None:
                unresolved_types[entity.kind].add(entity.type)
            else:
                by_name[(entity.kind, entity.name)].append(Endpoint(node, entity))
        for endpoints in by_name.values():
            endpoints.sort(key=lambda ep: ep.sort_key)
        node_counts = {key: len({_node_key(ep.node) for ep in eps}) for key, eps in by_name.items()}
        return cls(dict(by_name), node_counts, {kind: frozenset(types) for kind, types in unresolved_types.items()})

    def endpoints(self, kind: str) -> list[Endpoint]:
        """All resolved endpoints of one kind, in source order."""
        found = [ep for (k, _), eps in self.by_name.items() if k == kind for ep in eps]
        return sorted(found, key=lambda ep: ep.sort_key)

    def names(self, kind: str) -> list[str]:
        """The distinct resolved names used by one kind, sorted."""
        return sorted(name for k, name in self.by_name if k == kind)

    def using(self, kind: str, name: str) -> list[Endpoint]:
        """Endpoints of ``kind`` on ``name`` (empty when none)."""
        return self.by_name.get((kind, name), [])

    def one_way_namespaces(self, kind: str) -> frozenset[str]:
        """Namespaces other than ``/`` holding two or more names used with ``kind`` and none used with its peer.

        ``/fmu/out/...`` only ever subscribed, ``/local_costmap/clear_...`` only
        ever called: such a namespace is another program's interface.
        """
        counts: Counter[str] = Counter()
        peer_used: set[str] = set()
        peer_kind = PEER_KIND[kind]
        for k, name in self.by_name:
            if k == kind:
                counts[namespace_of(name)] += 1
            elif k == peer_kind:
                peer_used.add(namespace_of(name))
        return frozenset(ns for ns, n in counts.items() if n > 1 and ns != "/" and ns not in peer_used)

    def peers(self, endpoint: Endpoint) -> list[Endpoint]:
        """The endpoints at the other end of ``endpoint``'s name (subscriptions of a publisher's topic, ...)."""
        name = endpoint.entity.name
        return [] if name is None else self.using(PEER_KIND[endpoint.entity.kind], name)

    def unresolved_peer_may_match(self, endpoint: Endpoint) -> bool:
        """Whether an unresolved-name peer exists whose type does not rule out being ``endpoint``'s other end."""
        types = self.unresolved_types.get(PEER_KIND[endpoint.entity.kind], frozenset())
        own_type = endpoint.entity.type
        return bool(types) and (own_type is None or None in types or own_type in types)

    def wired_nodes(self, kind: str, exempt: ExemptNames) -> frozenset[int]:
        """``id()`` of every node with an endpoint of ``kind`` that reaches *another* node through a non-exempt name.

        Infrastructure names (``/tf``, ``/clock``, ...) do not count: sharing
        them says nothing about whether a node's publishers (say) feed the
        workspace's own data flow or only the world outside.
        """
        wired: set[int] = set()
        peer_kind = PEER_KIND[kind]
        for (k, name), endpoints in self.by_name.items():
            if k != kind or name in exempt:
                continue
            peer_nodes = {id(p.node) for p in self.using(peer_kind, name)}
            for ep in endpoints:
                if len(peer_nodes) > 1 or (peer_nodes and id(ep.node) not in peer_nodes):
                    wired.add(id(ep.node))
        return frozenset(wired)
