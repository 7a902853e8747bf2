"""One call from a workspace folder to its ROS graph: read, analyse, build.

``build_graph`` is the single entry point used by the CLI, the flake8 plugin and
the tests.  It never raises: unreadable files, broken stubs, budget exhaustion and
even internal errors become diagnostics on the returned graph.

The Python modules are analysed in groups that import nothing from one another
(:meth:`.Program.components`), each group on its own; what the graph needs is read
off each group's analysis (:mod:`.python_facts`) — or taken from the cache for a group
whose files did not change — and the groups' facts are merged before the C++ ends,
launch systems and interface definitions join them.
"""
from __future__ import annotations

import contextlib
import gc
import json
import traceback
from importlib.resources import files
from pathlib import Path
from typing import Callable, Sequence

from .absint.engine import Analysis
from .absint.library import LibraryModel, load_library
from .absint.program import Program
from .escaping import escape_text
from .graph.model import Diagnostic, RosGraph, RosNode, internal_error
from .interfaces.catalogue import generated_class_identity
from .launch.targets import entry_key, runs_module
from .metadata import WorkspaceMetadata, read_metadata
from .options import Buffers
from .python_facts import PythonFacts, facts_of, merged
from .safe_io import read_text
from .workspace import Outlines, load_workspace


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


def _library_loader(stub_files: Sequence[Path], diagnostics: list[Diagnostic]) -> Callable[[], LibraryModel]:
    """The library model, loaded when a group of modules is first analysed (a run whose groups all
    come from the cache never needs it), its problems added to ``diagnostics`` then — or at once
    when the user gives stub files, whose problems every run must report (the shipped stubs
    have none: tested)."""
    loaded: list[LibraryModel] = []

    def library() -> LibraryModel:
        if not loaded:
            model, problems = load_stubs(stub_files)
            diagnostics.extend(problems)
            loaded.append(model)
        return loaded[0]

    if stub_files:
        library()
    return library


def _launch_systems(root: Path, graph: RosGraph, python: PythonFacts, metadata: WorkspaceMetadata,
                    diagnostics: list[Diagnostic]) -> list:
    """The workspace's launch systems; a failure here must not cost the code-level graph."""
    from .launch.api import systems_for
    try:
        if not root.is_dir():  # one file given: its Python launch description, nothing around it walked
            return systems_for(root.parent, graph, python.launches, python.targets, diagnostics,
                               walk=False, packages=metadata.packages, frontend=[])
        return systems_for(root, graph, python.launches, python.targets, diagnostics,
                           packages=metadata.packages, frontend=metadata.launch_files)
    except Exception as exc:
        diagnostics.append(internal_error("launch files not analysed", exc))
        return []


#: Stores the C++ partner ends between runs: given how to read them, returns them (read or stored).
CppMemo = Callable[[Callable[[], tuple[list[RosNode], list[Diagnostic]]]], tuple[list[RosNode], list[Diagnostic]]]


def _cpp_nodes(root: Path, graph: RosGraph, diagnostics: list[Diagnostic], memo: CppMemo | None) -> None:
    """Add the workspace's rclcpp nodes (partner ends); a failure here must not cost the Python graph."""
    def read() -> tuple[list[RosNode], list[Diagnostic]]:
        from .cpp.to_graph import cpp_graph  # the parser loads only when the memo has no ends
        return cpp_graph(root)

    try:
        nodes, cpp_diagnostics = memo(read) if memo is not None else read()
    except Exception as exc:
        diagnostics.append(internal_error("C++ sources not read", exc))
        return
    diagnostics.extend(cpp_diagnostics)
    graph.nodes = sorted(graph.nodes + nodes, key=lambda n: (n.fqn or "", n.location, n.language))


def _interfaces(interface_dirs: Sequence[Path], graph: RosGraph, metadata: WorkspaceMetadata,
                diagnostics: list[Diagnostic]) -> None:
    """Interface definitions for the message rules (the workspace's own files as the metadata
    read them); a failure here must not cost the graph."""
    from .interfaces.catalogue import load_catalogue
    try:
        graph.interfaces = load_catalogue(None, interface_dirs, metadata.interface_files)
        diagnostics.extend(Diagnostic(path, 1, why) for path, why in graph.interfaces.problems)
    except Exception as exc:
        graph.interfaces = None
        diagnostics.append(internal_error("interface definitions not read", exc))


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
                cpp_memo: CppMemo | None = None, facts_memo: FactsMemo | None = None,
                metadata_memo: MetadataMemo | None = None, outlines: Outlines | None = None) -> RosGraph:
    """The ROS computation graph of the code under ``root`` (Python analysed, C++ partner ends); never raises.

    ``interface_dirs``: folders of extra interface packages (``.msg``/``.srv``/``.action``);
    ``buffers``: unsaved editor content that replaces files on disk; ``cpp_memo``, ``facts_memo``,
    ``metadata_memo``: where the C++ ends of an unchanged C++ tree, the facts of unchanged groups
    of Python modules and unchanged metadata are kept between runs (the cache); ``outlines``:
    what earlier runs learnt of each Python file, so that files whose group is kept are not parsed."""
    with collector_paused():
        return _build_graph(Path(root), stub_files, interface_dirs, buffers, cpp_memo, facts_memo,
                            metadata_memo, outlines)


def analyse(root: Path, stub_files: Sequence[Path] = (),
            interface_dirs: Sequence[Path] = ()) -> tuple[RosGraph, list[Analysis]]:
    """The graph and the analyses it was built from, one per group of modules (none after an
    internal error), for callers that explain the graph (``graph --explain``); never raises."""
    analyses: list[Analysis] = []
    with collector_paused():
        graph = _build_graph(Path(root), stub_files, interface_dirs, (), kept=analyses)
    return graph, analyses


#: Keeps the workspace's metadata between runs: given how to read it, returns it (stored or read).
MetadataMemo = Callable[[Callable[[], WorkspaceMetadata]], WorkspaceMetadata]

#: Keeps the facts of a group of modules between runs: given what identifies the group's inputs
#: and how to compute its facts, returns them (stored or computed, then stored).
FactsMemo = Callable[[str, Callable[[], PythonFacts]], PythonFacts]


def _group_facts(program: Program, library: Callable[[], LibraryModel], metadata: WorkspaceMetadata,
                 memo: FactsMemo | None,
                 kept: list[Analysis] | None) -> PythonFacts:
    """The facts of one group of modules (``program``), analysed on its own or kept from before;
    an internal error costs this group's facts only."""
    paths = {m.path for m in program.modules.values()}
    executables = sorted((exe for package in metadata.packages.packages.values()
                          for exe in package.executables.values()
                          if exe.language == "python" and runs_module(exe, program.modules, paths)),
                         key=entry_key)
    framework = {c: base for c, base in metadata.registered.items() if c.rpartition(".")[0] in program.modules}

    def compute() -> PythonFacts:
        analysis = Analysis(program, library(), framework_classes=framework)
        analysis.run()
        facts = facts_of(analysis, executables)
        if kept is not None:
            kept.append(analysis)
        else:
            analysis.close()  # frees the analysis by reference counting, not a later collection
        return facts

    try:
        if memo is None:
            return compute()
        inputs = json.dumps([[[m.name, m.path, m.is_package, m.program, m.digest]
                              for m in program.modules.values()],
                             sorted(framework.items()), [entry_key(exe) for exe in executables]])
        return memo(inputs, compute)
    except Exception as exc:
        first = min(paths, default="")
        where = traceback.extract_tb(exc.__traceback__)[-1]
        return PythonFacts(diagnostics=[Diagnostic(
            first, 1, f"modules analysed with this one not analysed: internal error: "
                      f"{type(exc).__name__}: {exc} (at {Path(where.filename).name}:{where.lineno})",
            "error")])


def _build_graph(root: Path, stub_files: Sequence[Path], interface_dirs: Sequence[Path],
                 buffers: Buffers, cpp_memo: CppMemo | None = None, facts_memo: FactsMemo | None = None,
                 metadata_memo: MetadataMemo | None = None, outlines: Outlines | None = None,
                 kept: list[Analysis] | None = None) -> RosGraph:
    diagnostics: list[Diagnostic] = []
    try:
        library = _library_loader(stub_files, diagnostics)
        metadata = metadata_memo(lambda: read_metadata(root)) if metadata_memo is not None \
            else read_metadata(root)
        diagnostics.extend(metadata.diagnostics)
        workspace = load_workspace(root, buffers, outlines,
                                   [root / rel for rel in metadata.python_files] if root.is_dir() else None)
        diagnostics.extend(workspace.diagnostics)
        program = Program(workspace.modules)
        python = merged([_group_facts(program.part(names), library, metadata, facts_memo, kept)
                         for names in program.components()])
        diagnostics.extend(python.diagnostics)
        graph = RosGraph(nodes=python.nodes, usage=python.usage, messages=python.messages)
        _cpp_nodes(root, graph, diagnostics, cpp_memo)
        graph.systems = _launch_systems(root, graph, python, metadata, diagnostics)
        _interfaces(interface_dirs, graph, metadata, diagnostics)
    except Exception as exc:  # the contract: a graph with a diagnostic, never a traceback
        where = traceback.extract_tb(exc.__traceback__)[-1]
        diagnostics.append(Diagnostic("", 0, f"internal error: {type(exc).__name__}: {exc} "
                                              f"(at {Path(where.filename).name}:{where.lineno})",
                                      "error"))
        graph = RosGraph()
        if kept is not None:
            kept.clear()
    # Paths and messages quote the analysed workspace: escaped, so that they print safely.
    graph.diagnostics = sorted({Diagnostic(escape_text(d.path), d.line, escape_text(d.message), d.severity)
                                for d in diagnostics})
    return graph
