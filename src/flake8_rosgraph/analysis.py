"""One call from a workspace folder to its ROS graph: read, analyse, build.

``build_graph`` is the single entry point used by the CLI, the flake8 plugin and
the tests.  It never raises: unreadable files, broken stubs, budget exhaustion and
even internal errors become diagnostics on the returned graph.
"""
from __future__ import annotations

import contextlib
import gc
import traceback
from importlib.resources import files
from pathlib import Path
from typing import Callable, Sequence

from .absint.engine import Analysis
from .absint.library import LibraryModel, load_library
from .absint.program import Program
from .escaping import escape_text
from .graph.builder import build_graph_from
from .graph.model import Diagnostic, RosGraph, RosNode
from .interfaces.catalogue import generated_class_identity
from .options import Buffers
from .registrations import registered_classes
from .safe_io import read_text
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
            texts.append((str(path), read_text(Path(path), None)))  # no FIFO, device or huge file
        except (OSError, UnicodeDecodeError) as exc:
            diagnostics.append(Diagnostic(str(path), 1, f"cannot read stub file: {exc}", "error"))
    library = load_library(texts)
    library.class_identity = generated_class_identity
    diagnostics.extend(Diagnostic(err.split(":", 1)[0], 1, "stub: " + err, "error")
                       for err in library.errors)
    return library, diagnostics


def _launch_systems(root: Path, graph: RosGraph, analysis: Analysis,
                    diagnostics: list[Diagnostic]) -> list:
    """The workspace's launch systems; a failure here must not cost the code-level graph."""
    from .launch.api import systems_for
    try:
        if not root.is_dir():  # one file given: its Python launch description, nothing around it walked
            return systems_for(root.parent, graph, analysis, diagnostics, walk=False)
        return systems_for(root, graph, analysis, diagnostics)
    except Exception as exc:
        diagnostics.append(Diagnostic("", 0, f"launch files not analysed: internal error: "
                                              f"{type(exc).__name__}: {exc}", "error"))
        return []


#: Stores the C++ partner ends between runs: given how to read them, returns them (read or stored).
CppMemo = Callable[[Callable[[], tuple[list[RosNode], list[Diagnostic]]]], tuple[list[RosNode], list[Diagnostic]]]


def _cpp_nodes(root: Path, graph: RosGraph, diagnostics: list[Diagnostic], memo: CppMemo | None) -> None:
    """Add the workspace's rclcpp nodes (partner ends); a failure here must not cost the Python graph."""
    from .cpp.to_graph import cpp_graph
    try:
        nodes, cpp_diagnostics = memo(lambda: cpp_graph(root)) if memo is not None else cpp_graph(root)
    except Exception as exc:
        diagnostics.append(Diagnostic("", 0, f"C++ sources not read: internal error: "
                                              f"{type(exc).__name__}: {exc}", "error"))
        return
    diagnostics.extend(cpp_diagnostics)
    graph.nodes = sorted(graph.nodes + nodes, key=lambda n: (n.fqn or "", n.location, n.language))


def _interfaces(root: Path, interface_dirs: Sequence[Path], graph: RosGraph,
                analysis: Analysis, diagnostics: list[Diagnostic]) -> None:
    """Message facts and interface definitions for the message rules; a failure here must not
    cost the graph."""
    from .graph.messages import message_facts
    from .interfaces.catalogue import load_catalogue
    try:
        graph.messages = message_facts(analysis)
        graph.interfaces = load_catalogue(root if root.is_dir() else None, interface_dirs)
        diagnostics.extend(Diagnostic(path, 1, why) for path, why in graph.interfaces.problems)
    except Exception as exc:
        graph.messages = graph.interfaces = None
        diagnostics.append(Diagnostic("", 0, f"message facts not gathered: internal error: "
                                              f"{type(exc).__name__}: {exc}", "error"))


@contextlib.contextmanager
def collector_paused():
    """Python's cyclic garbage collector off for the block, as it was after.

    The analysis allocates millions of small objects that live until it ends and
    form no garbage cycles, so every collection the allocations trigger scans an
    ever-growing heap for nothing (a quarter of the run time on a large workspace).
    """
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()


def build_graph(root: Path, stub_files: Sequence[Path] = (),
                interface_dirs: Sequence[Path] = (), buffers: Buffers = (),
                cpp_memo: CppMemo | None = None) -> RosGraph:
    """The ROS computation graph of the code under ``root`` (Python analysed, C++ partner ends); never raises.

    ``interface_dirs``: folders of extra interface packages (``.msg``/``.srv``/``.action``);
    ``buffers``: unsaved editor content that replaces files on disk; ``cpp_memo``: where the
    C++ ends of an unchanged C++ tree are kept between runs (the cache)."""
    with collector_paused():
        return _build_graph(Path(root), stub_files, interface_dirs, buffers, cpp_memo)[0]


def analyse(root: Path, stub_files: Sequence[Path] = (),
            interface_dirs: Sequence[Path] = ()) -> tuple[RosGraph, Analysis | None]:
    """The graph and the analysis it was built from (``None`` after an internal error), for
    callers that explain the graph (``graph --explain``); never raises."""
    with collector_paused():
        return _build_graph(Path(root), stub_files, interface_dirs, ())


def _build_graph(root: Path, stub_files: Sequence[Path], interface_dirs: Sequence[Path],
                 buffers: Buffers, cpp_memo: CppMemo | None = None) -> tuple[RosGraph, Analysis | None]:
    analysis: Analysis | None = None
    diagnostics: list[Diagnostic] = []
    try:
        library, stub_diags = load_stubs(stub_files)
        diagnostics.extend(stub_diags)
        workspace = load_workspace(root, buffers)
        diagnostics.extend(workspace.diagnostics)
        program = Program(workspace.modules)
        registered, registry_diags = registered_classes(root) if root.is_dir() else (frozenset(), [])
        diagnostics.extend(registry_diags)
        analysis = Analysis(program, library, framework_classes=registered)
        analysis.run()
        diagnostics.extend(Diagnostic(m.path, 1, why) for m, why in program.rejected)
        diagnostics.extend(Diagnostic(d.path, d.line, d.message, d.severity)
                           for d in analysis.diagnostics)
        graph = build_graph_from(analysis)
        diagnostics.extend(graph.diagnostics)
        _cpp_nodes(root, graph, diagnostics, cpp_memo)
        graph.systems = _launch_systems(root, graph, analysis, diagnostics)
        _interfaces(root, interface_dirs, graph, analysis, diagnostics)
        analysis.close()  # frees the analysis by reference counting, not a later collection
    except Exception as exc:  # the contract: a graph with a diagnostic, never a traceback
        where = traceback.extract_tb(exc.__traceback__)[-1]
        diagnostics.append(Diagnostic("", 0, f"internal error: {type(exc).__name__}: {exc} "
                                              f"(at {Path(where.filename).name}:{where.lineno})",
                                      "error"))
        graph = RosGraph()
        analysis = None
    # Paths and messages quote the analysed workspace: escaped, so that they print safely.
    graph.diagnostics = sorted({Diagnostic(escape_text(d.path), d.line, escape_text(d.message), d.severity)
                                for d in diagnostics})
    return graph, analysis
