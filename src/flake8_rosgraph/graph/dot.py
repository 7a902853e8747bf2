"""Graphviz DOT rendering of a :class:`~flake8_rosgraph.graph.model.RosGraph`, in the thesis's style.

The picture answers "who talks to whom" at a glance, so it follows the
computation graph figures of the LiSA thesis (chapter 6) and extends them to
services and actions:

* ROS node: ellipse filled aquamarine, labelled with its fully qualified name;
  one extra label line per timer (``timer 0.5 s``) and parameter
  (``param rate = 10``).
* topic: box filled yellow; **orange** when it has no publisher or no
  subscription in the graph (the thesis's "orphan" topics).
* service: ``shape=component`` filled light blue.
* action: ``shape=box3d`` filled plum.
* a name the analysis could not determine: one ``?`` vertex per kind (topic,
  service, action) with a dashed border; a node whose name or namespace is
  unknown gets its own dashed ellipse, labelled ``?``, since merging unknown
  nodes would invent connections.

Edges point the way requests or data are initiated: publisher node -> topic,
subscription topic -> node, service/action server node -> service/action,
client service/action -> node drawn dashed. When a node both publishes and
subscribes one topic, both edges of that loop are red (the thesis's loop).
Orphan status is judged on known names only; the rules, not the picture,
decide whether an unknown name could fill the gap.

Nodes with the same fully qualified name are drawn as one vertex, because at
run time they are one name in the ROS graph. The text is deterministic:
vertices and edges are sorted, and nothing depends on the input order.
"""
from __future__ import annotations

from dataclasses import dataclass, field

from .model import RosGraph, RosNode

#: For each named entity kind: the vertex kind of its name, whether the edge
#: leaves the node (``True``) or enters it, and whether it is drawn dashed.
_EDGE_KINDS: dict[str, tuple[str, bool, bool]] = {
    "publishers": ("topic", True, False),
    "subscriptions": ("topic", False, False),
    "services": ("service", True, False),
    "clients": ("service", False, True),
    "action_servers": ("action", True, False),
    "action_clients": ("action", False, True),
}
#: Shape and fill of each vertex kind.
_STYLES: dict[str, tuple[str, str]] = {
    "node": ("ellipse", "aquamarine"),
    "topic": ("box", "yellow"),
    "service": ("component", "lightblue"),
    "action": ("box3d", "plum"),
}
_ORPHAN_FILL = "orange"
_LOOP_COLOR = "red"
_UNKNOWN = "?"

_LEGEND = (
    "// Legend:",
    "//   ellipse, aquamarine   ROS node (label lines: timers, parameters)",
    "//   box, yellow           topic; orange = no publisher or no subscription",
    "//   component, lightblue  service",
    "//   box3d, plum           action",
    "//   dashed border         name the analysis could not determine (\"?\")",
    "//   node -> topic         publisher;  topic -> node  subscription",
    "//   red edges             a node subscribes to a topic it publishes (loop)",
    "//   node -> service       server;  service -> node (dashed)  client; same for actions",
)


def _quote(text: str) -> str:
    """A DOT double-quoted string holding ``text`` literally.

    Backslashes are doubled so that Graphviz escapes such as ``\\N`` or
    ``\\l`` in a name cannot change a label; line breaks become ``\\n``.
    """
    escaped = text.replace("\\", "\\\\").replace('"', '\\"')
    escaped = escaped.replace("\r\n", "\\n").replace("\n", "\\n").replace("\r", "\\n")
    return f'"{escaped}"'


@dataclass(frozen=True, order=True)
class _Edge:
    source: str
    target: str
    dashed: bool


def _node_key(node: RosNode) -> str:
    """The vertex id of a ROS node: its FQN, or its creation site when the FQN is unknown."""
    if node.fqn is not None:
        return "node:" + node.fqn
    return f"node?{node.location.path}:{node.location.line}:{node.location.column}"


def _node_title(node: RosNode) -> str:
    if node.fqn is not None:
        return node.fqn
    if node.name is not None:
        return f"{_UNKNOWN}/{node.name}"
    return _UNKNOWN


def _name_key(kind: str, name: str | None) -> str:
    # "topic?" can never equal "topic:" + a name, so an odd name cannot hijack the unknown box.
    return f"{kind}{_UNKNOWN}" if name is None else f"{kind}:{name}"


#: A label line and the key that orders it: timers by period, unknown periods, then parameters.
_DetailLine = tuple[tuple[int, float, str], str]


def _detail_lines(node: RosNode) -> set[_DetailLine]:
    """Timer and parameter label lines, each with the key that orders it (timers by period, then parameters)."""
    lines = set()
    for timer in node.of_kind("timers"):
        if timer.period is None:
            lines.add(((1, 0.0, ""), f"timer {_UNKNOWN} s"))
        else:
            lines.add(((0, timer.period, ""), f"timer {timer.period:g} s"))
    for param in node.of_kind("parameters"):
        text = f"param {param.name if param.name is not None else _UNKNOWN}"
        if param.default is not None:
            text += f" = {param.default!r}"
        lines.add(((2, 0.0, text), text))
    return lines


def _attributes(**attrs: str) -> str:
    return ", ".join(f"{key}={_quote(value)}" for key, value in attrs.items())


@dataclass
class _Drawing:
    """Vertices and edges gathered from the graph, keyed by DOT id, before any ordering is chosen."""

    node_titles: dict[str, str] = field(default_factory=dict)
    node_details: dict[str, set[_DetailLine]] = field(default_factory=dict)
    names: dict[str, tuple[str, str | None]] = field(default_factory=dict)  # vertex id -> (kind, name)
    edges: set[_Edge] = field(default_factory=set)
    publishes: set[tuple[str, str]] = field(default_factory=set)  # (node id, topic id), known names only
    subscribes: set[tuple[str, str]] = field(default_factory=set)

    def add(self, node: RosNode) -> None:
        key = _node_key(node)
        self.node_titles[key] = _node_title(node)
        self.node_details.setdefault(key, set()).update(_detail_lines(node))
        for entity in node.entities:
            if entity.kind not in _EDGE_KINDS:
                continue
            vertex_kind, outgoing, dashed = _EDGE_KINDS[entity.kind]
            name_key = _name_key(vertex_kind, entity.name)
            self.names[name_key] = (vertex_kind, entity.name)
            self.edges.add(_Edge(key, name_key, dashed) if outgoing else _Edge(name_key, key, dashed))
            if entity.name is None:
                continue  # an unknown name is no evidence of a loop or of a connection
            if entity.kind == "publishers":
                self.publishes.add((key, name_key))
            elif entity.kind == "subscriptions":
                self.subscribes.add((key, name_key))

    def node_lines(self) -> list[str]:
        shape, fill = _STYLES["node"]
        lines = []
        for key in sorted(self.node_titles):
            label = "\n".join([self.node_titles[key], *(text for _, text in sorted(self.node_details[key]))])
            style = "filled" if key.startswith("node:") else "filled,dashed"
            lines.append(f"  {_quote(key)} [{_attributes(label=label, shape=shape, style=style, fillcolor=fill)}];")
        return lines

    def name_lines(self) -> list[str]:
        published = {topic for _, topic in self.publishes}
        subscribed = {topic for _, topic in self.subscribes}
        lines = []
        for key in sorted(self.names):
            kind, name = self.names[key]
            shape, fill = _STYLES[kind]
            if name is None:
                attrs = _attributes(label=_UNKNOWN, shape=shape, style="dashed")
            else:
                if kind == "topic" and not (key in published and key in subscribed):
                    fill = _ORPHAN_FILL
                attrs = _attributes(label=name, shape=shape, style="filled", fillcolor=fill)
            lines.append(f"  {_quote(key)} [{attrs}];")
        return lines

    def edge_lines(self) -> list[str]:
        loops = self.publishes & self.subscribes
        lines = []
        for edge in sorted(self.edges):
            attrs = {}
            if edge.dashed:
                attrs["style"] = "dashed"
            if (edge.source, edge.target) in loops or (edge.target, edge.source) in loops:
                attrs["color"] = _LOOP_COLOR
            suffix = f" [{_attributes(**attrs)}]" if attrs else ""
            lines.append(f"  {_quote(edge.source)} -> {_quote(edge.target)}{suffix};")
        return lines


def to_dot(graph: RosGraph) -> str:
    """Render ``graph`` as DOT text (see the module docstring for the drawing conventions)."""
    drawing = _Drawing()
    for node in graph.nodes:
        drawing.add(node)
    lines = [
        "// ROS 2 computation graph extracted by flake8-rosgraph",
        *_LEGEND,
        "digraph rosgraph {",
        '  graph [rankdir="LR"];',
        '  node [fontname="Helvetica"];',
        *drawing.node_lines(),
        *drawing.name_lines(),
        *drawing.edge_lines(),
        "}",
    ]
    return "\n".join(lines) + "\n"
