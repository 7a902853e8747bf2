"""What every drawing of the graph shows, independent of the drawing format.

The DOT, Mermaid and HTML writers all answer "who talks to whom" the same way,
so the choice of vertices and edges lives here once:

* one vertex per ROS node *instance*: nodes with the same fully qualified name
  stay apart when they come from different programs (another source file, or
  another launch file entry), because the reader wants to see both programs;
  two creation sites of one program with the same name are one vertex;
* one vertex per topic, service and action name; one dashed ``?`` vertex per
  kind for names the analysis could not determine, and a node whose name is
  unknown stays on its own (merging unknowns would invent connections);
* edges follow the data: publisher node → topic → subscribing node, client
  node → service → server node, action client → action → action server;
* flags that the writers style: *exempt* names (infrastructure such as
  ``/rosout`` and the per-node parameter services, see :mod:`..rules.exempt`),
  *orphan* topics (no publisher or no subscription among known names), *loop*
  edges (a node subscribing to what it publishes), and the findings of the
  rules attached to the vertices and edges they are about.

Everything is sorted, so a picture — and every text made from it — is the same
for the same graph whatever the input order.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import PurePosixPath
from typing import Container, Iterable, Mapping

from ..findings import Finding
from .model import Entity, Location, RosGraph, RosNode

#: For each named entity kind: the vertex kind of its name, whether data flows from the
#: node to the name (``True``) or from the name to the node, and the edge's role.
EDGE_KINDS: dict[str, tuple[str, bool, str]] = {
    "publishers": ("topic", True, "publishes"),
    "subscriptions": ("topic", False, "subscribes"),
    "clients": ("service", True, "calls"),
    "services": ("service", False, "serves"),
    "action_clients": ("action", True, "sends goals"),
    "action_servers": ("action", False, "executes"),
}
UNKNOWN = "?"


@dataclass(frozen=True, order=True)
class EntityRow:
    """One entity of a node, as a side panel or a tooltip lists it."""

    kind: str
    name: str
    type: str
    where: str  # ``path:line``


@dataclass(frozen=True, order=True)
class FindingMark:
    """A rule finding as drawn: its code, message and where it is."""

    code: str
    message: str
    where: str


@dataclass
class Vertex:
    """A drawn vertex: a ROS node, or a topic, service or action name."""

    id: str
    kind: str  # "node" | "topic" | "service" | "action"
    label: str
    unknown: bool = False
    exempt: bool = False
    orphan: bool = False
    package: str | None = None
    namespace: str | None = None
    launch_files: set[str] = field(default_factory=set)
    details: set[tuple[tuple[int, float, str], str]] = field(default_factory=set)
    entities: set[EntityRow] = field(default_factory=set)
    findings: set[FindingMark] = field(default_factory=set)
    where: str = ""


@dataclass
class Edge:
    """A drawn edge in the direction data (or a request) flows."""

    source: str
    target: str
    role: str
    dashed: bool = False
    loop: bool = False
    findings: set[FindingMark] = field(default_factory=set)

    @property
    def key(self) -> tuple[str, str, str]:
        return (self.source, self.target, self.role)


@dataclass(frozen=True)
class NearMissLink:
    """Two name vertices a finding says were probably meant to be one (a likely typo)."""

    source: str
    target: str
    message: str


@dataclass
class Picture:
    """Vertices and edges in a fixed order, ready for any writer."""

    vertices: list[Vertex]
    edges: list[Edge]
    links: list[NearMissLink]

    def vertex(self, vertex_id: str) -> Vertex:
        return next(v for v in self.vertices if v.id == vertex_id)


def _where(location: Location) -> str:
    return f"{location.path}:{location.line}"


def _program(node: RosNode) -> str:
    """What tells one program from another: the launch entry, else the file that creates the node."""
    if node.launch is not None:
        return f"{node.launch.get('file')}:{node.launch.get('line')}"
    return node.location.path


def node_vertex_id(node: RosNode) -> str:
    """The vertex id of a node: FQN and program, or the creation site when the FQN is unknown."""
    if node.fqn is not None:
        return f"node:{node.fqn}@{_program(node)}"
    return f"node?{node.location.path}:{node.location.line}:{node.location.column}"


def _node_label(node: RosNode) -> str:
    if node.fqn is not None:
        return node.fqn
    if node.name is not None:
        return f"{UNKNOWN}/{node.name}"
    return UNKNOWN


def name_vertex_id(kind: str, name: str | None) -> str:
    # "topic?" can never equal "topic:" + a name, so an odd name cannot hijack the unknown vertex.
    return f"{kind}{UNKNOWN}" if name is None else f"{kind}:{name}"


def _details(node: RosNode) -> set[tuple[tuple[int, float, str], str]]:
    """Timer and parameter label lines, each with the key that orders it (timers by period, then parameters)."""
    lines = set()
    for timer in node.of_kind("timers"):
        if timer.period is None:
            lines.add(((1, 0.0, ""), f"timer {UNKNOWN} s"))
        else:
            lines.add(((0, timer.period, ""), f"timer {timer.period:g} s"))
    for param in node.of_kind("parameters"):
        text = f"param {param.name if param.name is not None else UNKNOWN}"
        if param.default is not None:
            text += f" = {param.default!r}"
        lines.add(((2, 0.0, text), text))
    return lines


def _row(entity: Entity) -> EntityRow:
    if entity.kind == "timers":
        name = f"{entity.period:g} s" if entity.period is not None else f"{UNKNOWN} s"
    else:
        name = entity.name if entity.name is not None else UNKNOWN
    return EntityRow(entity.kind.replace("_", " ").rstrip("s"), name, entity.type or "", _where(entity.location))


def package_of(path: str, package_folders: Mapping[str, str]) -> str | None:
    """The package whose folder (root-relative) holds ``path``: the deepest one wins."""
    best: tuple[int, str] | None = None
    for folder, name in package_folders.items():
        parts = PurePosixPath(folder).parts if folder not in ("", ".") else ()
        if PurePosixPath(path).parts[:len(parts)] == parts and (best is None or len(parts) > best[0]):
            best = (len(parts), name)
    return best[1] if best else None


class _Builder:
    def __init__(self, exempt: Container[str], package_folders: Mapping[str, str]) -> None:
        self.exempt = exempt
        self.package_folders = package_folders
        self.vertices: dict[str, Vertex] = {}
        self.edges: dict[tuple[str, str, str], Edge] = {}
        self.by_location: dict[Location, list[tuple[str, Edge | None]]] = {}
        self.publishes: set[tuple[str, str]] = set()
        self.subscribes: set[tuple[str, str]] = set()

    def add_node(self, node: RosNode) -> None:
        key = node_vertex_id(node)
        vertex = self.vertices.get(key)
        if vertex is None:
            vertex = self.vertices[key] = Vertex(
                key, "node", _node_label(node), unknown=node.fqn is None,
                package=package_of(node.location.path, self.package_folders),
                namespace=node.namespace, where=_where(node.location))
        if node.launch is not None and node.launch.get("file"):
            vertex.launch_files.add(str(node.launch["file"]))
        vertex.details |= _details(node)
        vertex.entities |= {_row(e) for e in node.entities}
        self.by_location.setdefault(node.location, []).append((key, None))
        for entity in node.entities:
            self._add_entity(key, entity)

    def _add_entity(self, node_key: str, entity: Entity) -> None:
        if entity.kind not in EDGE_KINDS:
            self.by_location.setdefault(entity.location, []).append((node_key, None))
            return
        vertex_kind, outgoing, role = EDGE_KINDS[entity.kind]
        name_key = name_vertex_id(vertex_kind, entity.name)
        if name_key not in self.vertices:
            self.vertices[name_key] = Vertex(
                name_key, vertex_kind, entity.name if entity.name is not None else UNKNOWN,
                unknown=entity.name is None,
                exempt=entity.name is not None and entity.name in self.exempt)
        source, target = (node_key, name_key) if outgoing else (name_key, node_key)
        dashed = entity.kind in ("clients", "action_clients")
        edge = self.edges.setdefault((source, target, role), Edge(source, target, role, dashed=dashed))
        self.by_location.setdefault(entity.location, []).append((node_key, edge))
        if entity.name is not None and entity.kind == "publishers":
            self.publishes.add((node_key, name_key))
        elif entity.name is not None and entity.kind == "subscriptions":
            self.subscribes.add((node_key, name_key))

    def mark_findings(self, findings: Iterable[Finding]) -> list[NearMissLink]:
        links = set()
        for finding in findings:
            mark = FindingMark(finding.code, finding.message, _where(finding.location))
            hits = self.by_location.get(finding.location, [])
            for node_key, edge in hits:
                self.vertices[node_key].findings.add(mark)
                if edge is not None:
                    edge.findings.add(mark)
            ends = [self._name_end(edge) for _, edge in hits if edge is not None]
            for related, _label in finding.related:
                for _, other in self.by_location.get(related, []):
                    if other is None:
                        continue
                    for end in ends:
                        partner = self._name_end(other)
                        if end != partner and self.vertices[end].kind == self.vertices[partner].kind:
                            links.add(NearMissLink(*sorted((end, partner)), finding.message))
        return sorted(links, key=lambda link: (link.source, link.target, link.message))

    def _name_end(self, edge: Edge) -> str:
        return edge.target if self.vertices[edge.target].kind != "node" else edge.source

    def picture(self, links: list[NearMissLink]) -> Picture:
        published = {topic for _, topic in self.publishes}
        subscribed = {topic for _, topic in self.subscribes}
        for vertex in self.vertices.values():
            if vertex.kind == "topic" and not vertex.unknown:
                vertex.orphan = not (vertex.id in published and vertex.id in subscribed)
        loops = self.publishes & self.subscribes
        for edge in self.edges.values():
            edge.loop = (edge.source, edge.target) in loops or (edge.target, edge.source) in loops
        return Picture(sorted(self.vertices.values(), key=lambda v: v.id),
                       sorted(self.edges.values(), key=lambda e: e.key), links)


def build_picture(graph: RosGraph, findings: Iterable[Finding] = (), exempt: Container[str] = frozenset(),
                  package_folders: Mapping[str, str] | None = None) -> Picture:
    """The picture of ``graph``, with ``findings`` (rule :class:`~..findings.Finding`) drawn on it.

    ``exempt`` answers ``name in exempt`` for names the rules skip
    (:class:`~..rules.exempt.ExemptNames`); ``package_folders`` maps
    root-relative package folders to package names, for the package filter.
    """
    builder = _Builder(exempt, package_folders or {})
    for node in graph.nodes:
        builder.add_node(node)
    links = builder.mark_findings(findings)
    return builder.picture(links)
