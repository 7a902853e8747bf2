"""An index of the graph's named endpoints, built in one pass, that the wiring rules query.

Every wiring rule asks the same questions — "who else uses this name with the
other role?", "could an entity whose name we could not resolve be that other
end?", "does this node talk to anybody?" — and answering them by rescanning
the graph per entity would make the rules quadratic in the workspace size.

Test fixtures form their own systems (:mod:`.fixtures`): :meth:`EndpointIndex.peers`
and the other "who talks to whom" questions only pair ends that can run together.
"""
from __future__ import annotations

from collections import Counter, defaultdict
from dataclasses import dataclass, field

from ..graph.model import NAMED_KINDS, PEER_KIND, Entity, RosGraph, RosNode
from .exempt import ExemptNames
from .fixtures import node_scope, sees, test_run
from .shared import once

#: What is known of an endpoint whose name is not: its message type and how its name ends.
Unresolved = tuple["str | None", "str | None"]


@dataclass(frozen=True)
class Endpoint:
    """An entity together with the node that creates it (the model's entities do not point back)."""

    node: RosNode
    entity: Entity
    #: The node's fixture scope (:func:`.fixtures.node_scope`); ``None`` for production code.
    scope: str | None = None

    def sees(self, other: Endpoint) -> bool:
        """Whether ``other`` can be this end's partner: production and test fixtures do not mix.

        A production end belongs to the package under test when its node or the end itself is
        created there: a package's code may create its ends on a node another package's class
        makes (a framework's shared node, a library base class)."""
        own_run, other_run = self.run, other.run
        if own_run is not None and other_run is not None and own_run != other_run:
            return False  # two test modules never run together
        return self.spells_like(other)

    def spells_like(self, other: Endpoint) -> bool:
        """Whether ``other``'s name shows how this end's name is meant to be spelt: an end it
        can run with, or one of another test module of its scope (two tests of one package
        write the product's topic alike, though they never run together)."""
        return sees(self.scope, other.scope, other.node.location.path) or (
            self.scope is not None and other.scope is None
            and sees(self.scope, None, other.entity.location.path))

    def spells_for(self, other: Endpoint) -> bool:
        """Whether ``other``'s spelling of a name is evidence of how this end meant to spell
        it: :meth:`spells_like`, or, for a test fixture, any production end (a test script
        beside the workspace, ``scripts/test_flash.py``, calls the product's services by their
        names: a misspelling of one is a slip, though the product is outside its scope)."""
        return self.spells_like(other) or (self.scope is not None and other.scope is None)

    @property
    def run(self) -> str | None:
        """The test module whose run the end belongs to (:func:`.fixtures.test_run`)."""
        return test_run(self.node)

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
    #: What is known of the unresolved endpoints, by kind: ``(message type, name suffix)``
    #: (``None`` = unknown; see :attr:`~flake8_rosgraph.graph.model.Entity.name_suffix`).
    unresolved_types: dict[str, frozenset[Unresolved]] = field(default_factory=dict)
    #: The same, of production nodes only: a fixture's unknown cannot fill a production gap.
    unresolved_production_types: dict[str, frozenset[Unresolved]] = field(default_factory=dict)
    #: Production ends of unknown name *and* type, by kind: ``(name suffix, node)``. Such an end
    #: (a test harness or recorder whose topics come from a plan at run time) could be any
    #: topic, so it fills only gaps near it (:func:`near`), never the whole workspace's.
    untyped_unresolved: dict[str, tuple[tuple["str | None", RosNode], ...]] = field(default_factory=dict)
    #: Production ends whose name a launch file makes unknown (a parameter it sets to a launch
    #: argument, a parameter file it hands that the analysis cannot read), by kind: ``(message
    #: type, name suffix, node)``. The unknown is one configuration of one launch system, so it
    #: fills only gaps near it (:func:`near`), never the whole workspace's.
    launch_unresolved: dict[str, tuple[tuple["str | None", "str | None", RosNode], ...]] = field(default_factory=dict)
    #: :meth:`same_role_nodes` answers by (kind, name, scope, test run): every end of one
    #: scope and run sees the same users.
    _role_counts: dict[tuple[str, str, str | None, str | None], int] = field(default_factory=dict, repr=False)

    @classmethod
    def build(cls, graph: RosGraph) -> EndpointIndex:
        """The index of ``graph``'s ends (one for all the rules of a run: :mod:`.shared`)."""
        return once("endpoints", graph, lambda: cls._build(graph))

    @classmethod
    def _build(cls, graph: RosGraph) -> EndpointIndex:
        by_name: dict[tuple[str, str], list[Endpoint]] = defaultdict(list)
        unresolved_types: dict[str, set[Unresolved]] = defaultdict(set)
        unresolved_production: dict[str, set[Unresolved]] = defaultdict(set)
        untyped: dict[str, list[tuple[str | None, RosNode]]] = defaultdict(list)
        by_launch: dict[str, list[tuple[str | None, str | None, RosNode]]] = defaultdict(list)
        scopes: dict[int, str | None] = {}
        for node, entity in graph.entities():
            if entity.kind not in NAMED_KINDS:
                continue
            if id(node) not in scopes:
                scopes[id(node)] = node_scope(node)
            scope = scopes[id(node)]
            if entity.name is None:
                unresolved_types[entity.kind].add((entity.type, entity.name_suffix))
                if scope is None and entity.type is None:
                    untyped[entity.kind].append((entity.name_suffix, node))
                elif scope is None and entity.name_set_at is not None:
                    by_launch[entity.kind].append((entity.type, entity.name_suffix, node))
                elif scope is None:
                    unresolved_production[entity.kind].add((entity.type, entity.name_suffix))
            else:
                by_name[(entity.kind, entity.name)].append(Endpoint(node, entity, scope))
        for endpoints in by_name.values():
            endpoints.sort(key=lambda ep: ep.sort_key)
        return cls(dict(by_name), _frozen(unresolved_types), _frozen(unresolved_production),
                   {kind: tuple(ends) for kind, ends in untyped.items()},
                   {kind: tuple(ends) for kind, ends in by_launch.items()})

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
        for (k, name), endpoints in self.by_name.items():
            if k == kind:
                counts[namespace_of(name)] += 1
            elif k == peer_kind and not all(ep.entity.partial for ep in endpoints):
                peer_used.add(namespace_of(name))  # a partly known name is no evidence of use
        return frozenset(ns for ns, n in counts.items() if n > 1 and ns != "/" and ns not in peer_used)

    def peers(self, endpoint: Endpoint) -> list[Endpoint]:
        """The endpoints at the other end of ``endpoint``'s name (subscriptions of a publisher's topic, ...)."""
        name = endpoint.entity.name
        if name is None:
            return []
        return [p for p in self.using(PEER_KIND[endpoint.entity.kind], name) if endpoint.sees(p)]

    def same_role_nodes(self, endpoint: Endpoint) -> int:
        """How many distinct nodes ``endpoint`` can run with use its name in its role (itself included).

        Nodes of one fully qualified name count once (see :func:`_node_key`).
        """
        key = (endpoint.entity.kind, endpoint.entity.name or "", endpoint.scope, endpoint.run)
        if key not in self._role_counts:
            users = self.using(key[0], key[1])
            self._role_counts[key] = len({_node_key(ep.node) for ep in users if endpoint.sees(ep)})
        return self._role_counts[key]

    def unresolved_peer_may_match(self, endpoint: Endpoint) -> bool:
        """Whether an unresolved-name peer exists whose type and known name end do not rule
        out being ``endpoint``'s other end: an unknown stays local to the names it could be."""
        unresolved = self.unresolved_types if endpoint.scope is not None else self.unresolved_production_types
        own_type, own_name = endpoint.entity.type, endpoint.entity.name or ""
        peer_kind = PEER_KIND[endpoint.entity.kind]
        return any((own_type is None or peer_type is None or peer_type == own_type)
                   and (suffix is None or own_name.endswith(suffix))
                   for peer_type, suffix in unresolved.get(peer_kind, ())) or (
            endpoint.scope is None and any(
                (suffix is None or own_name.endswith(suffix)) and near(node, endpoint.node)
                for suffix, node in self.untyped_unresolved.get(peer_kind, ()))) or (
            endpoint.scope is None and any(
                (own_type is None or peer_type is None or peer_type == own_type)
                and (suffix is None or own_name.endswith(suffix)) and near(node, endpoint.node)
                for peer_type, suffix, node in self.launch_unresolved.get(peer_kind, ())))

    def wired_nodes(self, kind: str, exempt: ExemptNames) -> frozenset[int]:
        """``id()`` of every node with an endpoint of ``kind`` that reaches *another* node through a non-exempt name.

        Another node has another fully qualified name (:func:`_node_key`): launched
        copies of one driver class that several executables share (one adds a raw-data
        publisher in its ``main``, another the matching subscription) are one node
        talking to itself, which says nothing about whether its outputs feed the workspace.
        Infrastructure names (``/tf``, ``/clock``, ...) do not count: sharing
        them says nothing about whether a node's publishers (say) feed the
        workspace's own data flow or only the world outside. Nor do partly known
        names (``param if launched else '/scan'``): the node may use another one.
        """
        wired: set[int] = set()
        for (k, name), endpoints in self.by_name.items():
            if k != kind or name in exempt:
                continue
            peer_nodes_by_scope: dict[tuple[str | None, str | None], set[str | int]] = {}
            for ep in endpoints:
                if ep.entity.partial:
                    continue
                # Ends of one scope and test run see the same peers: compute them once for each.
                seen_from = (ep.scope, ep.run)
                if seen_from not in peer_nodes_by_scope:
                    peer_nodes_by_scope[seen_from] = {_node_key(p.node) for p in self.peers(ep)
                                                      if not p.entity.partial}
                peer_nodes = peer_nodes_by_scope[seen_from]
                if len(peer_nodes) > 1 or (peer_nodes and _node_key(ep.node) not in peer_nodes):
                    wired.add(id(ep.node))
        return frozenset(wired)


def _frozen(types: dict[str, set[Unresolved]]) -> dict[str, frozenset[Unresolved]]:
    return {kind: frozenset(found) for kind, found in types.items()}


def package_folder(path: str) -> str:
    """The folder of the ROS package a source file most likely lies in, from the path alone:
    the parent of an ament_python package's module folder of the same name
    (``src/nav/nav/planner.py`` -> ``src/nav``), else the parent of the file's folder
    (``ros/dance/scripts/head.py`` -> ``ros/dance``)."""
    parts = path.split("/")[:-1]
    for index in range(len(parts) - 1, 0, -1):
        if parts[index] == parts[index - 1]:
            return "/".join(parts[:index])
    return "/".join(parts[:-1])


def near(a: RosNode, b: RosNode) -> bool:
    """Whether two nodes are close enough for an end of unknown name and type on one to stand
    for the other's missing partner: one package, or started by one launch file."""
    if package_folder(a.location.path) == package_folder(b.location.path):
        return True
    return a.launch is not None and b.launch is not None and a.launch.get("file") == b.launch.get("file")
