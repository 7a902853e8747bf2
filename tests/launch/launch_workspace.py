"""Writing a small workspace of launch and package files, and the one launch system it holds."""
from __future__ import annotations

from pathlib import Path

from flake8_rosgraph.analysis import build_graph
from flake8_rosgraph.graph.model import RosGraph
from flake8_rosgraph.launch.model import System


def one_system(root: Path, files: dict[str, str]) -> tuple[RosGraph, System]:
    """Write ``files`` (root-relative path → text) under ``root``; the graph and its only system."""
    for rel, text in files.items():
        (root / rel).parent.mkdir(parents=True, exist_ok=True)
        (root / rel).write_text(text)
    graph = build_graph(root)
    (system,) = graph.systems
    return graph, system
