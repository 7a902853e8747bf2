"""The graph as one self-contained, interactive HTML page (``graph --format html``).

People would rather look at a ROS graph than read JSON, and the page must work
where it is opened — a CI artifact, an air-gapped robot laptop — so it holds
everything itself: the data, the layout, the styles and a small script of our
own (``assets/view.js``, ``assets/view.css``; no third-party code, nothing
fetched at view time).

The layout is computed here, in Python (:mod:`.layout`: layered left to right
by data flow), so the script only draws, filters and answers clicks. A page
holds one or more *views*: the code-level graph and, when launch files are
found (or one is asked for), the system each launch file starts. Findings of
the rules are drawn on the vertices and edges they are about; a near-miss pair
is linked.
"""
from __future__ import annotations

import json
from dataclasses import dataclass
from importlib.resources import files
from typing import Any, Iterable

from .layout import layered_layout
from .picture import FindingMark, Picture, Vertex

#: Approximate text metrics of the page's font (drawing units), to size vertices before drawing.
CHAR_WIDTH = 7.2
LINE_HEIGHT = 16.0
PADDING = 14.0
MAX_LABEL_LINES = 4


@dataclass(frozen=True)
class View:
    """One picture to show, with its title (``code-level graph``, a launch file, …)."""

    key: str
    title: str
    picture: Picture


def _label_lines(vertex: Vertex) -> list[str]:
    lines = [vertex.label]
    if vertex.kind == "node":
        details = [text for _, text in sorted(vertex.details)]
        if len(details) > MAX_LABEL_LINES - 1:
            details = details[:MAX_LABEL_LINES - 2] + [f"+{len(details) - (MAX_LABEL_LINES - 2)} more"]
        lines.extend(details)
    return lines


def _size(lines: list[str]) -> tuple[float, float]:
    return (max(len(line) for line in lines) * CHAR_WIDTH + 2 * PADDING, len(lines) * LINE_HEIGHT + PADDING)


def _marks(marks: Iterable[FindingMark]) -> list[dict[str, str]]:
    return [{"code": m.code, "message": m.message, "where": m.where} for m in sorted(marks)]


def _view_data(view: View) -> dict[str, Any]:
    picture = view.picture
    lines = {v.id: _label_lines(v) for v in picture.vertices}
    layout = layered_layout([(e.source, e.target) for e in picture.edges], {k: _size(v) for k, v in lines.items()})
    boxes = layout.boxes
    index = {v.id: i for i, v in enumerate(picture.vertices)}
    vertices = []
    for vertex in picture.vertices:
        box = boxes[vertex.id]
        vertices.append({
            "id": vertex.id, "kind": vertex.kind, "label": lines[vertex.id],
            "x": round(box.x, 1), "y": round(box.y, 1), "w": round(box.width, 1), "h": round(box.height, 1),
            "unknown": vertex.unknown, "exempt": vertex.exempt, "orphan": vertex.orphan,
            "package": vertex.package, "namespace": vertex.namespace, "where": vertex.where,
            "launch": sorted(vertex.launch_files),
            "entities": [[row.kind, row.name, row.type, row.where] for row in sorted(vertex.entities)],
            "findings": _marks(vertex.findings),
        })
    return {
        "key": view.key, "title": view.title, "vertices": vertices,
        "edges": [{"s": index[e.source], "t": index[e.target], "role": e.role, "dashed": e.dashed,
                   "loop": e.loop, "findings": _marks(e.findings),
                   "via": [[round(x, 1), round(y, 1)] for x, y in layout.routes.get((e.source, e.target), [])]}
                  for e in picture.edges],
        "links": [{"s": index[link.source], "t": index[link.target], "message": link.message}
                  for link in picture.links],
    }


def _asset(name: str) -> str:
    return files("flake8_rosgraph.graph").joinpath("assets", name).read_text(encoding="utf-8")


def _script_json(data: Any) -> str:
    """JSON safe inside ``<script>``: no ``</`` can close the element, no ``<!--`` can open a comment."""
    text = json.dumps(data, ensure_ascii=True, sort_keys=False, separators=(",", ":"))
    return text.replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026")


def to_html(views: list[View], title: str) -> str:
    """The page: every view's layout and data, the stylesheet and the script, in one file."""
    data = {"title": title, "views": [_view_data(view) for view in views]}
    escaped_title = title.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
    return (
        "<!DOCTYPE html>\n"
        '<html lang="en">\n<head>\n<meta charset="utf-8">\n'
        '<meta name="viewport" content="width=device-width, initial-scale=1">\n'
        "<meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; "
        "style-src 'unsafe-inline'; script-src 'unsafe-inline'; img-src data:\">\n"
        f"<title>{escaped_title} - ROS graph</title>\n"
        f"<style>\n{_asset('view.css')}</style>\n</head>\n<body>\n"
        f'<script type="application/json" id="rosgraph-data">{_script_json(data)}</script>\n'
        f"<script>\n{_asset('view.js')}</script>\n</body>\n</html>\n"
    )
