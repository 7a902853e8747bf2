"""The measured steps on one workspace, and running them round-robin.

Steps: interpreter start-up (the fixed cost of every subprocess row), ``ast.parse``
of every file in-process (the floor: no checker can avoid reading and parsing),
pyflakes, flake8 ``-j1`` without the plugin, flake8 ``-j1`` with it (cold: its
cache removed; warm: cache present, nothing changed; one file changed: one
file's content edited, so the cache key misses; a topic misspelt in a leaf module,
so a finding changes; flake8 on that one edited file, as pre-commit runs it), and
the standalone ``graph`` command, and the peer tool ros2inspector's graph of the same tree
when it is installed. All our subprocess steps run in the interpreter running the benchmark.

Each repetition runs every step once, in this order, so that slow drift in
machine load (other work on the same host) hits all steps alike instead of
whichever step happens to run last.
"""
from __future__ import annotations

import ast
import contextlib
import json
import os
import re
import shutil
import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Iterator, Sequence

from flake8_rosgraph.cache import CACHE_DIR_NAME

from measure import CommandFailed, Sample, Summary, run_command

#: The distribution whose flake8 plugin is measured.
PLUGIN_DIST = "flake8-rosgraph"
LAUNCHER = Path(__file__).resolve().parent / "flake8_launcher.py"
#: flake8's default ``--exclude`` (directories), so the floor parses the files flake8 checks.
FLAKE8_EXCLUDED = frozenset({".svn", "CVS", ".bzr", ".hg", ".git", "__pycache__", ".tox", ".nox", ".eggs"})
#: flake8 and pyflakes exit 1 when they report something; that is success here.
CHECKER_OK = frozenset({0, 1})
_ROS_CODE = re.compile(r":\d+:\d+: ROS\d{3} ")
#: The packages the measured commands import (those installed), compiled to bytecode in place.
_COMPILE_MEASURED = """
import compileall, importlib.util, os
for name in ("flake8_rosgraph", "flake8", "pyflakes", "pycodestyle", "mccabe", "networkx", "sarif_om",
             "jschema_to_python", "tree_sitter_cpp", "tomli"):
    spec = importlib.util.find_spec(name)
    if spec is not None and spec.origin is not None:
        place = os.path.dirname(spec.origin) if spec.submodule_search_locations else spec.origin
        (compileall.compile_dir if os.path.isdir(place) else compileall.compile_file)(place, quiet=1)
"""


@dataclass(frozen=True)
class Corpus:
    """The Python files of a workspace, as flake8 would find them."""

    root: Path
    files: tuple[Path, ...]
    lines: int

    @classmethod
    def scan(cls, root: Path) -> Corpus:
        files = []
        for directory, dirnames, filenames in os.walk(root):
            dirnames[:] = sorted(d for d in dirnames
                                 if d not in FLAKE8_EXCLUDED and not d.endswith(".egg"))
            files += [Path(directory, name) for name in sorted(filenames) if name.endswith(".py")]
        lines = sum(len(path.read_bytes().splitlines()) for path in files)
        return cls(root, tuple(sorted(files)), lines)


@dataclass(frozen=True)
class Step:
    """One measured action. ``measure`` gets the repetition number (0, 1, …)."""

    key: str
    label: str
    measure: Callable[[int], Sample]
    describe: Callable[[str], str]


def run_steps(steps: Sequence[Step], runs: int) -> dict[str, Summary]:
    """Every step ``runs`` times, round-robin; summaries by step key, in step order."""
    samples: dict[str, list[Sample]] = {step.key: [] for step in steps}
    for repetition in range(runs):
        for step in steps:
            samples[step.key].append(step.measure(repetition))
    return {step.key: Summary(step.label, tuple(samples[step.key])) for step in steps}


def _count_reported(stdout: str) -> str:
    lines = stdout.splitlines()
    ros = sum(1 for line in lines if _ROS_CODE.search(line))
    return f"{len(lines)} reported, {ros} ROS"


def _describe_graph(stdout: str) -> str:
    graph = json.loads(stdout)
    return f"{len(graph['nodes'])} nodes, {len(graph['diagnostics'])} diagnostics"


def _describe_peer_graph(stdout: str) -> str:
    graph = json.loads(stdout)
    return f"{len(graph['nodes'])} nodes and topics, {len(graph['edges'])} edges"


class WorkspaceBench:
    """Builds the steps for one workspace directory (which it may edit: give it a copy)."""

    def __init__(self, corpus: Corpus, python: str = sys.executable) -> None:
        self.corpus = corpus
        self.python = python
        self.root = corpus.root
        # The plugin must analyse exactly this directory, whatever lies above it. Python runs
        # from the bytecode an installation leaves (see :func:`compile_measured`), as for users.
        self.env = {k: v for k, v in os.environ.items()
                    if not k.startswith("ROSGRAPH_") and k != "PYTHONDONTWRITEBYTECODE"}
        self.env["ROSGRAPH_ROOT"] = str(self.root)
        self.cache_dir = self.root / CACHE_DIR_NAME

    def compile_measured(self) -> None:
        """Compile the measured packages' bytecode before any timing, as ``pip install`` does.

        Without it, under ``PYTHONDONTWRITEBYTECODE`` (some CI images and containers set it)
        or with an editable install never imported yet, every measured process would compile
        its imports from source again: a cost users do not pay, and more of it for the
        plugin's many modules than for flake8's."""
        run_command([self.python, "-c", _COMPILE_MEASURED], self.root, self.env)

    def _flake8(self, with_plugin: bool, jobs: str = "1") -> Sample:
        hide = [] if with_plugin else ["--hide", PLUGIN_DIST]
        return run_command([self.python, str(LAUNCHER), *hide, "--", f"--jobs={jobs}", "."],
                           self.root, self.env, CHECKER_OK)

    def flake8_version(self, with_plugin: bool) -> str:
        """``flake8 --version``: the loaded plugins, as the launcher sets them up."""
        hide = [] if with_plugin else ["--hide", PLUGIN_DIST]
        return run_command([self.python, str(LAUNCHER), *hide, "--", "--version"],
                           self.root, self.env).stdout

    # -- the steps --------------------------------------------------------------------------

    def startup(self) -> Step:
        return Step("startup", "python -c pass (start-up, reference)",
                    lambda _: run_command([self.python, "-c", "pass"], self.root, self.env),
                    lambda _: "")

    def ast_parse(self) -> Step:
        def measure(_: int) -> Sample:
            wall, cpu = time.perf_counter(), time.process_time()
            for path in self.corpus.files:
                try:
                    ast.parse(path.read_bytes(), filename=str(path))
                except SyntaxError:  # flake8 reports E999 for these and goes on; so does the floor
                    pass
            return Sample(time.perf_counter() - wall, time.process_time() - cpu, None, "")

        return Step("ast", "ast.parse, all files (in-process)", measure,
                    lambda _: f"{len(self.corpus.files)} files")

    def pyflakes(self) -> Step:
        return Step("pyflakes", "pyflakes (subprocess)",
                    lambda _: run_command([self.python, "-m", "pyflakes", "."], self.root, self.env,
                                          CHECKER_OK),
                    _count_reported)

    def flake8_without(self) -> Step:
        return Step("flake8", "flake8 -j1 without plugin", lambda _: self._flake8(False), _count_reported)

    def flake8_cold(self) -> Step:
        def measure(_: int) -> Sample:
            shutil.rmtree(self.cache_dir, ignore_errors=True)
            return self._flake8(True)

        return Step("cold", "flake8 -j1 + plugin, cold (no cache)", measure, _count_reported)

    def flake8_without_auto(self) -> Step:
        return Step("flake8-auto", "flake8 --jobs=auto without plugin",
                    lambda _: self._flake8(False, "auto"), _count_reported)

    def flake8_cold_auto(self) -> Step:
        """Wall time is what counts here: the workers run side by side (CPU adds up)."""
        def measure(_: int) -> Sample:
            shutil.rmtree(self.cache_dir, ignore_errors=True)
            return self._flake8(True, "auto")

        return Step("cold-auto", "flake8 --jobs=auto + plugin, cold", measure, _count_reported)

    def flake8_warm(self) -> Step:
        """Must follow :meth:`flake8_cold` in the step list: it relies on the cache that run left."""
        def measure(_: int) -> Sample:
            if not self.cache_dir.is_dir():
                raise CommandFailed(f"no {CACHE_DIR_NAME}/ after the cold run: the warm run would be cold")
            return self._flake8(True)

        return Step("warm", "flake8 -j1 + plugin, warm (cache, no change)", measure, _count_reported)

    def flake8_one_changed(self) -> Step:
        """Edit the largest file (a comment line, new each repetition), measure, restore it."""
        edited = max(self.corpus.files, key=lambda p: (p.stat().st_size, str(p)))

        def measure(repetition: int) -> Sample:
            original = edited.read_bytes()
            newline = b"" if original.endswith(b"\n") else b"\n"
            edited.write_bytes(original + newline + f"# rosgraph-bench edit {repetition}\n".encode())
            try:
                return self._flake8(True)
            finally:
                edited.write_bytes(original)

        rel = edited.relative_to(self.root).as_posix()
        return Step("changed", "flake8 -j1 + plugin, one file changed", measure,
                    lambda out: f"{_count_reported(out)}; edited {rel}")

    def flake8_topic_renamed(self, edit: LeafEdit) -> Step:
        """Misspell a topic in a module nothing imports (a new slip each repetition), measure, restore."""
        def measure(repetition: int) -> Sample:
            with edit.applied(repetition):
                return self._flake8(True)

        return Step("renamed", "flake8 -j1 + plugin, topic renamed in a leaf module", measure,
                    lambda out: f"{_count_reported(out)}; {edit.describe(self.root)}")

    def precommit(self, edit: LeafEdit, with_plugin: bool) -> Step:
        """flake8 on the edited file only, as pre-commit runs it, the cache left by the runs before."""
        hide = [] if with_plugin else ["--hide", PLUGIN_DIST]
        rel = edit.path.relative_to(self.root).as_posix()

        def measure(repetition: int) -> Sample:
            with edit.applied(repetition, doubled=True):
                return run_command([self.python, str(LAUNCHER), *hide, "--", "--jobs=1", rel],
                                   self.root, self.env, CHECKER_OK)

        key, label = ("precommit", "pre-commit: flake8 + plugin on the edited file") if with_plugin \
            else ("precommit-without", "pre-commit: flake8 without plugin on the edited file")
        return Step(key, label, measure, _count_reported)

    def graph(self, jobs: int | None = None) -> Step:
        """The ``graph`` command: with every core (its default), or with ``jobs`` processes."""
        more = [] if jobs is None else ["--jobs", str(jobs)]
        key, label = ("graph", "graph command (--format json)") if jobs is None else \
            (f"graph-{jobs}", f"graph command (--format json --jobs {jobs})")
        return Step(key, label,
                    lambda _: run_command([self.python, "-m", "flake8_rosgraph", "graph", ".",
                                           "--format", "json", *more], self.root, self.env),
                    _describe_graph)

    def peer_graph(self, peer: str) -> Step:
        """The peer tool's communication graph of the same tree, its cache off (as ``graph``
        keeps none): what ``graph`` is compared with."""
        return Step("peer-graph", "ros2inspector graph comms (peer tool, --no-cache)",
                    lambda _: run_command([peer, "--quiet", "graph", "comms", "--path", ".", "--format", "json",
                                           "--no-cache"], self.root, self.env),
                    _describe_peer_graph)


#: Leaf-module topic literals tried, in order, for one whose rename changes a finding.
TRIED_EDITS = 5


@dataclass(frozen=True)
class LeafEdit:
    """A topic literal of a subscription or publisher in a module no other module imports."""

    path: Path
    line: int
    start: int          # byte offsets of the literal's text inside its line
    end: int
    topic: str

    @classmethod
    def find(cls, root: Path) -> LeafEdit | None:
        """The first such literal by path whose rename changes the findings, among the first
        :data:`TRIED_EDITS`: of subscriptions whose topic some other node publishes, then of any
        subscription, then of publishers (the first of all when none does); ``None`` when there
        is none."""
        from flake8_rosgraph.absint.program import Program
        from flake8_rosgraph.analysis import build_graph
        from flake8_rosgraph.workspace import load_workspace

        graph = build_graph(root)
        published = {(e.name, n.location) for n in graph.nodes for e in n.entities if e.kind == "publishers"}
        connected = {(e.location.path, e.location.line) for n in graph.nodes for e in n.entities
                     if e.kind == "subscriptions" and any(name == e.name and at != n.location
                                                          for name, at in published)}
        program = Program(load_workspace(root).modules)
        imported = {".".join(name.split(".")[:end]) for names in program.imports.values()
                    for name in names for end in range(1, name.count(".") + 2)}
        found = []
        for module in program.modules.values():
            if module.name in imported:
                continue
            for call in ast.walk(module.tree):
                if isinstance(call, ast.Call) and isinstance(call.func, ast.Attribute) \
                        and call.func.attr in ("create_subscription", "create_publisher") \
                        and len(call.args) > 1 and isinstance(call.args[1], ast.Constant) \
                        and isinstance(call.args[1].value, str) and call.args[1].end_lineno == call.args[1].lineno:
                    literal = call.args[1]
                    rank = 0 if (module.path, call.lineno) in connected else \
                        1 if call.func.attr == "create_subscription" else 2
                    found.append((rank, module.path, literal.lineno,
                                  literal.col_offset, literal.end_col_offset, literal.value))
        edits = [cls(root / path, line, start, end, topic) for _, path, line, start, end, topic in sorted(found)]
        return next((edit for edit in edits[:TRIED_EDITS] if edit.changes_findings(root)), edits[0] if edits else None)

    def changes_findings(self, root: Path) -> bool:
        """Whether the rename changes the workspace's findings (analysed uncached, before measuring):
        a renamed end some rule excuses (a test fixture's, one fed from outside) shows nothing."""
        from flake8_rosgraph.cache import build_report
        from flake8_rosgraph.options import Settings

        before = build_report(root, Settings()).findings
        with self.applied(0):
            return build_report(root, Settings()).findings != before

    @contextlib.contextmanager
    def applied(self, variant: int, doubled: bool = False) -> Iterator[None]:
        """The file with the topic misspelt for the block, then as it was: a letter dropped (or
        ``doubled``) counting from the end, ``variant`` letters in — a slip of the pen, which the
        rules report with "did you mean", and a different text for each variant."""
        index = max(0, len(self.topic) - 1 - variant % len(self.topic))
        letter = self.topic[index]
        typo = self.topic[:index] + (letter * 2 if doubled else "") + self.topic[index + 1:]
        original = self.path.read_bytes()
        lines = original.split(b"\n")
        text = lines[self.line - 1]
        lines[self.line - 1] = text[:self.start] + repr(typo).encode() + text[self.end:]
        self.path.write_bytes(b"\n".join(lines))
        try:
            yield
        finally:
            self.path.write_bytes(original)

    def describe(self, root: Path) -> str:
        return f"misspelt '{self.topic}' in {self.path.relative_to(root).as_posix()}:{self.line}"
