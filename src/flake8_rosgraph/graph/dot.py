"""Graphviz DOT rendering of a :class:`~flake8_rosgraph.graph.model.RosGraph`, in the thesis's style.

The picture answers "who talks to whom" at a glance (vertices and edges are
chosen once, in :mod:`.picture`), so it follows the computation graph figures
of the LiSA thesis (chapter 6) and extends them to services and actions:

* ROS node: ellipse filled aquamarine, labelled with its fully qualified name;
  one extra label line per timer (``timer 0.5 s``) and parameter
  (``param rate = 10``). Nodes with one name from different programs are
  drawn apart.
* topic: box filled yellow; **orange** when it has no publisher or no
  subscription in the graph (the thesis's "orphan" topics).
* service: ``shape=component`` filled light blue; action: ``shape=box3d``
  filled plum.
* infrastructure names (``/rosout``, ``/tf``, parameter services — the rules'
  exempt list) are grey with grey edges: present, but not what the reader
  looks for.
* a name the analysis could not determine: one ``?`` vertex per kind with a
  dashed border; a node whose name is unknown gets its own dashed ellipse.

Edges follow the data: publisher node -> topic -> subscribing node, and
client -> service -> server (client edges dashed), the same for actions. A
node that subscribes to what it publishes has both edges of that loop red.
Ranks run left to right, and the legend is a cluster of its own, so it shows
in the rendered image. The text is deterministic.
"""
from __future__ import annotations

from typing import Container, Iterable

from ..findings import Finding
from .model import RosGraph
from .picture import Edge, Picture, Vertex, build_picture

#: Shape and fill of each vertex kind.
_STYLES: dict[str, tuple[str, str]] = {
    "node": ("ellipse", "aquamarine"),
    "topic": ("box", "yellow"),
    "service": ("component", "lightblue"),
    "action": ("box3d", "plum"),
}
_ORPHAN_FILL = "orange"
_EXEMPT_FILL = "gray92"
_EXEMPT_COLOR = "gray60"
_LOOP_COLOR = "red"

#: The legend cluster: (id, label, shape, fill, style) per sample vertex, and sample edges.
_LEGEND_VERTICES = (
    ("legend:node", "ROS node\n(timers, parameters)", "ellipse", "aquamarine", "filled"),
    ("legend:topic", "topic", "box", "yellow", "filled"),
    ("legend:orphan", "topic without publisher\nor subscription", "box", _ORPHAN_FILL, "filled"),
    ("legend:service", "service", "component", "lightblue", "filled"),
    ("legend:action", "action", "box3d", "plum", "filled"),
    ("legend:exempt", "infrastructure\n(/rosout, /tf, ...)", "box", _EXEMPT_FILL, "filled"),
    ("legend:unknown", "name not known\nstatically", "box", "white", "dashed"),
)
_LEGEND_EDGES = (
    ("legend:node", "legend:topic", {"label": "publishes"}),
    ("legend:topic", "legend:orphan", {"label": "loop", "color": _LOOP_COLOR}),
    ("legend:node", "legend:service", {"label": "calls", "style": "dashed"}),
)


def _quote(text: str) -> str:
    """A DOT double-quoted string holding ``text`` literally.

    Backslashes are doubled so that Graphviz escapes such as ``\\N`` or
    ``\\l`` in a name cannot change a label; line breaks become ``\\n``.
    """
    escaped = text.replace("\\", "\\\\").replace('"', '\\"')
    escaped = escaped.replace("\r\n", "\\n").replace("\n", "\\n").replace("\r", "\\n")
    return f'"{escaped}"'


def _attributes(**attrs: str) -> str:
    return ", ".join(f"{key}={_quote(value)}" for key, value in attrs.items())


def _vertex_line(vertex: Vertex) -> str:
    shape, fill = _STYLES[vertex.kind]
    if vertex.kind == "node":
        label = "\n".join([vertex.label, *(text for _, text in sorted(vertex.details))])
        attrs = _attributes(label=label, shape=shape, style="filled,dashed" if vertex.unknown else "filled",
                            fillcolor=fill)
    elif vertex.unknown:
        attrs = _attributes(label=vertex.label, shape=shape, style="dashed")
    elif vertex.exempt:
        attrs = _attributes(label=vertex.label, shape=shape, style="filled", fillcolor=_EXEMPT_FILL,
                            color=_EXEMPT_COLOR, fontcolor=_EXEMPT_COLOR)
    else:
        attrs = _attributes(label=vertex.label, shape=shape, style="filled",
                            fillcolor=_ORPHAN_FILL if vertex.orphan else fill)
    return f"  {_quote(vertex.id)} [{attrs}];"


def _edge_line(edge: Edge, exempt: set[str]) -> str:
    attrs = {}
    if edge.dashed:
        attrs["style"] = "dashed"
    if edge.loop:
        attrs["color"] = _LOOP_COLOR
    elif edge.source in exempt or edge.target in exempt:
        attrs["color"] = _EXEMPT_COLOR
    suffix = f" [{_attributes(**attrs)}]" if attrs else ""
    return f"  {_quote(edge.source)} -> {_quote(edge.target)}{suffix};"


def _legend_lines() -> list[str]:
    lines = ["  subgraph cluster_legend {", '    graph [label="Legend", style="rounded", color="gray60"];']
    for key, label, shape, fill, style in _LEGEND_VERTICES:
        lines.append(f"    {_quote(key)} [{_attributes(label=label, shape=shape, style=style, fillcolor=fill)}];")
    for source, target, attrs in _LEGEND_EDGES:
        lines.append(f"    {_quote(source)} -> {_quote(target)} [{_attributes(**attrs)}];")
    lines.append("  }")
    return lines


def picture_to_dot(picture: Picture) -> str:
    """DOT text of a picture (see the module docstring for the drawing conventions)."""
    exempt = {v.id for v in picture.vertices if v.exempt}
    lines = [
        "// ROS 2 computation graph extracted by flake8-rosgraph (legend: cluster_legend)",
        "digraph rosgraph {",
        '  graph [rankdir="LR", ranksep="1.2", nodesep="0.25"];',
        '  node [fontname="Helvetica"];',
        *_legend_lines(),
        *(_vertex_line(v) for v in picture.vertices),
        *(_edge_line(e, exempt) for e in picture.edges),
        "}",
    ]
    return "\n".join(lines) + "\n"


def to_dot(graph: RosGraph, findings: Iterable[Finding] = (), exempt: Container[str] = frozenset()) -> str:
    """Render ``graph`` as DOT text; ``exempt`` names are drawn subdued."""
    return picture_to_dot(build_picture(graph, findings, exempt))
