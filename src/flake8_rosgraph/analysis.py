"""One call from a workspace folder to its ROS graph: read, analyse, build.

``build_graph`` is the single entry point used by the CLI, the flake8 plugin and
the tests.  It never raises: unreadable files, broken stubs, budget exhaustion and
even internal errors become diagnostics on the returned graph.

The Python modules are analysed in groups that import nothing from one another
(:meth:`.Program.components`), each group on its own — side by side in forked processes
where the run allows more than one (:mod:`.forked`), while this process reads the C++
sources; what the graph needs is read off each group's analysis (:mod:`.python_facts`) — or
taken from the cache for a group whose files did not change — and the groups' facts are
merged, in the groups' order, before the C++ ends, launch systems and interface definitions
join them.
"""
from __future__ import annotations

import contextlib
import functools
import gc
import hashlib
import json
import pickle
import traceback
from dataclasses import dataclass
from importlib.resources import files
from pathlib import Path
from typing import Callable, Protocol, Sequence

from . import forked, inventory
from .absint.engine import Analysis
from .absint.library import LibraryModel, load_library
from .absint.program import Program
from .absint.values import const
from .escaping import escape_text
from .graph.model import Diagnostic, RosGraph, RosNode, internal_error
from .interfaces.catalogue import generated_class_identity
from .interfaces.constants import ConstantValue, interface_constants
from .launch.packages import Executable
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
    library.closed_class = lambda qualname: generated_class_identity(qualname) is not None
    diagnostics.extend(Diagnostic(err.split(":", 1)[0], 1, "stub: " + err, "error")
                       for err in library.errors)
    return library, diagnostics


def _library_loader(stub_files: Sequence[Path], diagnostics: list[Diagnostic],
                    constants: dict[str, ConstantValue]) -> Callable[[], LibraryModel]:
    """The library model, loaded when a group of modules is first analysed (a run whose groups all
    come from the cache never needs it), its problems added to ``diagnostics`` then — or at once
    when the user gives stub files, whose problems every run must report (the shipped stubs
    have none: tested). ``constants``: those of the workspace's interface files, which the
    generated classes the code imports hold (a stub's own model of a name wins)."""
    loaded: list[LibraryModel] = []

    def library() -> LibraryModel:
        if not loaded:
            model, problems = load_stubs(stub_files)
            for name, value in constants.items():
                model.constants.setdefault(name, const(value))
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


def _cpp_nodes(root: Path, diagnostics: list[Diagnostic], memo: CppMemo | None) -> list[RosNode]:
    """The workspace's rclcpp nodes (partner ends); a failure here must not cost the Python graph."""
    def read() -> tuple[list[RosNode], list[Diagnostic]]:
        from .cpp.to_graph import cpp_graph  # the parser loads only when the memo has no ends
        return cpp_graph(root)

    try:
        nodes, cpp_diagnostics = memo(read) if memo is not None else read()
    except Exception as exc:
        diagnostics.append(internal_error("C++ sources not read", exc))
        return []
    diagnostics.extend(cpp_diagnostics)
    return nodes


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
    with collector_paused(), inventory.shared(root):
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


class FactsMemo(Protocol):
    """Keeps the facts of groups of modules between runs (:class:`.facts_cache.FactsStore`), each
    under what identifies the group's inputs."""

    def read(self, inputs: str) -> PythonFacts | None:
        """The kept facts of the group with these ``inputs``, or ``None``."""

    def holds(self, inputs: str) -> bool:
        """Whether facts are kept for these ``inputs``, without reading them (they may still
        prove unreadable: :meth:`read` says ``None`` then)."""

    def write(self, inputs: str, facts: PythonFacts) -> None:
        """Keep the facts computed for the group with these ``inputs``."""


@dataclass
class _Group:
    """One group of modules (:meth:`.Program.components`), with what its facts depend on
    besides its files: the Python executables that run it and its classes frameworks build."""

    program: Program
    executables: list[Executable]
    framework: dict[str, str]
    #: A digest of the workspace's interface constants (:func:`.interface_constants`), which
    #: the analysis reads where code imports them.
    constants: str

    @classmethod
    def of(cls, program: Program, metadata: WorkspaceMetadata, constants: str) -> _Group:
        paths = {m.path for m in program.modules.values()}
        executables = sorted((exe for package in metadata.packages.packages.values()
                              for exe in package.executables.values()
                              if exe.language == "python" and runs_module(exe, program.modules, paths)),
                             key=entry_key)
        framework = {c: base for c, base in metadata.registered.items()
                     if c.rpartition(".")[0] in program.modules}
        return cls(program, executables, framework, constants)

    @functools.cached_property
    def inputs(self) -> str:
        """What identifies the group's facts: its modules' names, paths and contents, and the rest."""
        return json.dumps([[[m.name, m.path, m.is_package, m.program, m.digest]
                            for m in self.program.modules.values()],
                           sorted(self.framework.items()), [entry_key(exe) for exe in self.executables],
                           self.constants])

    @functools.cached_property
    def weight(self) -> int:
        """About how much analysing it costs: its lines."""
        return sum(max(m.lines, 1) for m in self.program.modules.values())

    def facts(self, library: Callable[[], LibraryModel], memo: FactsMemo | None,
              kept: list[Analysis] | None) -> PythonFacts:
        """The group analysed on its own (its facts then kept by ``memo``); an internal error
        costs this group's facts only."""
        try:
            analysis = Analysis(self.program, library(), framework_classes=self.framework)
            analysis.run()
            facts = facts_of(analysis, self.executables)
            if kept is not None:
                kept.append(analysis)
            else:
                analysis.close()  # frees the analysis by reference counting, not a later collection
        except Exception as exc:
            first = min((m.path for m in self.program.modules.values()), default="")
            where = traceback.extract_tb(exc.__traceback__)[-1]
            return PythonFacts(diagnostics=[Diagnostic(
                first, 1, f"modules analysed with this one not analysed: internal error: "
                          f"{type(exc).__name__}: {exc} (at {Path(where.filename).name}:{where.lineno})",
                "error")])
        if memo is not None:
            memo.write(self.inputs, facts)
        return facts


#: Reading a group's kept facts costs about this fraction of analysing it (both by its lines;
#: navigation2 + ros2cli: 0.07 s against 5 s).
KEPT_READ_RATIO = 64


@dataclass
class _GroupsFacts:
    """The facts of every group: kept ones read at once, the others analysed — in forked
    processes (:mod:`.forked`) while the caller goes on, where the run allows more than one."""

    groups: list[_Group]
    library: Callable[[], LibraryModel]
    memo: FactsMemo | None
    kept: list[Analysis] | None
    found: list[PythonFacts | None]
    running: forked.ForkedJobs | None = None

    @classmethod
    def start(cls, groups: list[_Group], library: Callable[[], LibraryModel], memo: FactsMemo | None,
              kept: list[Analysis] | None) -> _GroupsFacts:
        held = [memo is not None and memo.holds(group.inputs) for group in groups]
        started = cls(groups, library, memo, kept, [None] * len(groups))
        missing = [index for index, known in enumerate(held) if not known]
        # --explain reads the analyses themselves: they run here
        count = 0 if kept is not None else forked.useful(
            [groups[index].weight for index in missing],
            meanwhile=sum(group.weight for group, known in zip(groups, held) if known) // KEPT_READ_RATIO)
        if count:
            library()  # loaded before the fork, once for every child
            started.running = forked.ForkedJobs.start(
                sorted(missing, key=lambda index: (-groups[index].weight, index)), started._pickled, count)
        if memo is not None:  # while the children analyse
            started.found = [memo.read(group.inputs) if known else None for group, known in zip(groups, held)]
        return started

    def _pickled(self, index: int) -> bytes | None:
        """In a child: the facts of group ``index``, pickled for the parent (``None`` when they
        cannot be: the parent analyses that group again)."""
        facts = self.groups[index].facts(self.library, self.memo, None)
        try:
            return pickle.dumps(facts, protocol=pickle.HIGHEST_PROTOCOL)
        except Exception:  # whatever pickling raises: the parent analyses the group itself
            return None

    def finish(self) -> list[PythonFacts]:
        """Every group's facts, in the groups' order (whichever process computed them)."""
        if self.running is not None:
            for index, data in self.running.collect().items():
                self.found[index] = pickle.loads(data)
        return [facts if facts is not None else group.facts(self.library, self.memo, self.kept)
                for group, facts in zip(self.groups, self.found)]


def _build_graph(root: Path, stub_files: Sequence[Path], interface_dirs: Sequence[Path],
                 buffers: Buffers, cpp_memo: CppMemo | None = None, facts_memo: FactsMemo | None = None,
                 metadata_memo: MetadataMemo | None = None, outlines: Outlines | None = None,
                 kept: list[Analysis] | None = None) -> RosGraph:
    diagnostics: list[Diagnostic] = []
    try:
        metadata = metadata_memo(lambda: read_metadata(root)) if metadata_memo is not None \
            else read_metadata(root)
        diagnostics.extend(metadata.diagnostics)
        constants = interface_constants(metadata.interface_files)
        library = _library_loader(stub_files, diagnostics, constants)
        constants_key = hashlib.sha256(json.dumps(sorted(constants.items())).encode()).hexdigest()
        workspace = load_workspace(root, buffers, outlines,
                                   [root / rel for rel in metadata.python_files] if root.is_dir() else None)
        diagnostics.extend(workspace.diagnostics)
        program = Program(workspace.modules)
        groups = _GroupsFacts.start([_Group.of(program.part(names), metadata, constants_key)
                                     for names in program.components()], library, facts_memo, kept)
        cpp = _cpp_nodes(root, diagnostics, cpp_memo)  # meanwhile, if groups run in other processes
        python = merged(groups.finish())
        diagnostics.extend(python.diagnostics)
        nodes = sorted(python.nodes + cpp, key=lambda n: (n.fqn or "", n.location, n.language))
        graph = RosGraph(nodes=nodes, usage=python.usage, messages=python.messages)
        graph.systems = _launch_systems(root, graph, python, metadata, diagnostics)
        graph.policies = metadata.policy_profiles
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
