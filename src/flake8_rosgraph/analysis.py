"""One call from a workspace folder to its ROS graph: read, analyse, build.

``build_graph`` is the single entry point used by the CLI, the flake8 plugin and
the tests.  It never raises: unreadable files, broken stubs, budget exhaustion and
even internal errors become diagnostics on the returned graph.
"""
from __future__ import annotations

import traceback
from importlib.resources import files
from pathlib import Path
from typing import Sequence

from .absint.engine import Analysis
from .absint.library import LibraryModel, load_library
from .absint.program import Program
from .graph.builder import build_graph_from
from .graph.model import Diagnostic, RosGraph
from .workspace import load_workspace


def builtin_stub_texts() -> list[tuple[str, str]]:
    """The stub files shipped in the package, as ``(name, text)``, in name order."""
    folder = files("flake8_rosgraph.stubs")
    return [(entry.name, entry.read_text(encoding="utf-8"))
            for entry in sorted(folder.iterdir(), key=lambda e: e.name)
            if entry.name.endswith(".toml")]


def load_stubs(stub_files: Sequence[Path] = ()) -> tuple[LibraryModel, list[Diagnostic]]:
    texts = builtin_stub_texts()
    diagnostics: list[Diagnostic] = []
    for path in stub_files:
        try:
            texts.append((str(path), Path(path).read_text(encoding="utf-8")))
        except (OSError, UnicodeDecodeError) as exc:
            diagnostics.append(Diagnostic(str(path), 1, f"cannot read stub file: {exc}", "error"))
    library = load_library(texts)
    diagnostics.extend(Diagnostic(err.split(":", 1)[0], 1, "stub: " + err, "error")
                       for err in library.errors)
    return library, diagnostics


def _launch_systems(root: Path, graph: RosGraph, analysis: Analysis,
                    diagnostics: list[Diagnostic]) -> list:
    """The workspace's launch systems; a failure here must not cost the code-level graph."""
    from .launch.api import systems_for
    try:
        return systems_for(root if root.is_dir() else root.parent, graph, analysis)
    except Exception as exc:
        diagnostics.append(Diagnostic("", 0, f"launch files not analysed: internal error: "
                                              f"{type(exc).__name__}: {exc}", "error"))
        return []


def build_graph(root: Path, stub_files: Sequence[Path] = ()) -> RosGraph:
    """The ROS computation graph of the Python code under ``root``; never raises."""
    return analyse(root, stub_files)[0]


def analyse(root: Path, stub_files: Sequence[Path] = ()) -> tuple[RosGraph, Analysis | None]:
    """The graph and the analysis it was built from (``None`` after an internal error), for
    callers that explain the graph (``graph --explain``); never raises."""
    root = Path(root)
    analysis: Analysis | None = None
    diagnostics: list[Diagnostic] = []
    try:
        library, stub_diags = load_stubs(stub_files)
        diagnostics.extend(stub_diags)
        workspace = load_workspace(root)
        diagnostics.extend(workspace.diagnostics)
        program = Program(workspace.modules)
        analysis = Analysis(program, library)
        analysis.run()
        diagnostics.extend(Diagnostic(m.path, 1, why) for m, why in program.rejected)
        diagnostics.extend(Diagnostic(d.path, d.line, d.message, d.severity)
                           for d in analysis.diagnostics)
        graph = build_graph_from(analysis)
        graph.systems = _launch_systems(root, graph, analysis, diagnostics)
    except Exception as exc:  # the contract: a graph with a diagnostic, never a traceback
        where = traceback.extract_tb(exc.__traceback__)[-1]
        diagnostics.append(Diagnostic("", 0, f"internal error: {type(exc).__name__}: {exc} "
                                              f"(at {Path(where.filename).name}:{where.lineno})",
                                      "error"))
        graph = RosGraph()
        analysis = None
    graph.diagnostics = sorted(set(diagnostics))
    return graph, analysis
