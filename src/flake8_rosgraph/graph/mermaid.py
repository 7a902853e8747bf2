"""Mermaid flowchart rendering of the graph, for pull-request comments and Markdown.

GitHub renders a fenced ``mermaid`` block as a diagram, so a PR comment can
show the ROS graph a change produces. The diagram uses the same vertices and
edges as the DOT and HTML views (:mod:`.picture`): ROS nodes as stadiums,
topics as boxes, services as subroutine boxes, actions as hexagons; edges
follow the data (client edges dotted); orphan topics orange, loops red.
Infrastructure names (``/rosout``, ``/tf``, parameter services) are left out,
with a comment saying how many: a PR diagram is read, not browsed.

Vertex ids are ``v0``, ``v1``, … in vertex order and every label is quoted
with Mermaid's entity escapes, so no name can break the syntax.
"""
from __future__ import annotations

from typing import Container, Iterable

from ..findings import Finding
from .model import RosGraph
from .picture import Picture, build_picture

_SHAPES: dict[str, tuple[str, str]] = {
    "node": ('(["', '"])'),
    "topic": ('["', '"]'),
    "service": ('[["', '"]]'),
    "action": ('{{"', '"}}'),
}
_CLASSES = (
    "classDef rosnode fill:#7fffd4,stroke:#2f6f5f",
    "classDef topic fill:#ffff99,stroke:#888800",
    "classDef orphan fill:#ffa500,stroke:#aa5500",
    "classDef service fill:#add8e6,stroke:#336677",
    "classDef action fill:#dda0dd,stroke:#663366",
    "classDef unknown fill:#ffffff,stroke:#666666,stroke-dasharray:4 3",
)
_SAFE = frozenset("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789 /_.:~?=-()")


def _label(text: str) -> str:
    """``text`` as Mermaid label content: line breaks as ``<br>``, everything unusual as ``#NNN;``."""
    lines = text.splitlines() or [""]
    return "<br>".join("".join(ch if ch in _SAFE else f"#{ord(ch)};" for ch in line) for line in lines)


def picture_to_mermaid(picture: Picture) -> str:
    """Mermaid ``flowchart LR`` text of a picture, infrastructure names left out."""
    shown = [v for v in picture.vertices if not v.exempt]
    ids = {vertex.id: f"v{index}" for index, vertex in enumerate(shown)}
    lines = ["flowchart LR"]
    hidden = len(picture.vertices) - len(shown)
    if hidden:
        lines.append(f"  %% {hidden} infrastructure names hidden (/rosout, /tf, parameter services, ...)")
    classes: dict[str, list[str]] = {}
    for vertex in shown:
        opening, closing = _SHAPES[vertex.kind]
        text = vertex.label
        if vertex.kind == "node" and vertex.details:
            text = "\n".join([vertex.label, *(line for _, line in sorted(vertex.details))])
        lines.append(f"  {ids[vertex.id]}{opening}{_label(text)}{closing}")
        style = ("unknown" if vertex.unknown else "orphan" if vertex.orphan
                 else "rosnode" if vertex.kind == "node" else vertex.kind)
        classes.setdefault(style, []).append(ids[vertex.id])
    loops = []
    index = 0
    for edge in picture.edges:
        if edge.source not in ids or edge.target not in ids:
            continue
        arrow = "-.->" if edge.dashed else "-->"
        lines.append(f"  {ids[edge.source]} {arrow} {ids[edge.target]}")
        if edge.loop:
            loops.append(str(index))
        index += 1
    for link in picture.links:
        if link.source in ids and link.target in ids:
            lines.append(f"  {ids[link.source]} -. \"did you mean?\" .- {ids[link.target]}")
            loops.append(str(index))
            index += 1
    lines.extend(f"  {line}" for line in _CLASSES)
    lines.extend(f"  class {','.join(members)} {style}" for style, members in sorted(classes.items()))
    if loops:
        lines.append(f"  linkStyle {','.join(loops)} stroke:#ff0000,stroke-width:2px")
    return "\n".join(lines) + "\n"


def to_mermaid(graph: RosGraph, findings: Iterable[Finding] = (), exempt: Container[str] = frozenset()) -> str:
    """Render ``graph`` as a Mermaid flowchart (``exempt`` names are left out)."""
    return picture_to_mermaid(build_picture(graph, findings, exempt))
