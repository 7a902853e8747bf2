"""``package`` + ``executable`` → the code-level nodes that executable creates.

An entry point ``module:function`` (or an installed script's module top
level) starts a task of the analysis; the nodes it creates are the ``node``
effects of every task reachable from there.  Calls are read off the engine's
dependency record: a task that read the return summary ``("ret", t)`` called
``t``, and one that read a module global ``("g", m, …)`` imported ``m``
(whose top level ran).

Where each Python executable leads is read from the analysis of the modules it runs
(:class:`EntryReach`, kept with that group's facts); :class:`TargetIndex` answers
launch files from those answers, whichever group each came from.
"""
from __future__ import annotations

from collections import deque
from typing import Mapping

from ..absint.engine import Analysis
from ..absint.values import Obj
from ..graph.builder import _class_name
from ..graph.model import Location
from .model import ExecutableRef
from .packages import Executable, PackageIndex


def entry_key(exe: Executable) -> str:
    """What a Python executable runs, as a key of :attr:`TargetIndex.python` (``module:function``
    of an entry point, ``script:PATH`` of an installed script)."""
    return f"{exe.module}:{exe.function or ''}" if exe.module is not None else f"script:{exe.script}"


def _entry_text(exe: Executable) -> str | None:
    """``module:function`` (or the script) the executable runs, for the JSON output."""
    if exe.module is not None:
        return f"{exe.module}:{exe.function}" if exe.function else exe.module
    return exe.script


def runs_module(exe: Executable, names: Mapping[str, object], paths: set[str]) -> bool:
    """Whether ``exe`` runs one of the modules ``names`` (files ``paths``)."""
    return exe.module in names if exe.module is not None else exe.script in paths


class TargetIndex:
    """Resolves launch files' ``package`` + ``executable`` against the workspace's packages and
    ``python``, where each Python executable leads (by :func:`entry_key`; ``None``: the Python
    code was not analysed)."""

    def __init__(self, python: Mapping[str, ExecutableRef] | None, packages: PackageIndex) -> None:
        self.python = python
        self.packages = packages

    def resolve(self, package: str | None, executable: str | None) -> ExecutableRef:
        if package is None or executable is None:
            return ExecutableRef("unknown")
        found = self.packages.packages.get(package)
        if found is None:
            return ExecutableRef("missing-package")
        exe = found.executables.get(executable)
        if exe is None:
            status = "missing-executable" if found.complete else "unknown"
            return ExecutableRef(status, known=tuple(sorted(found.executables)))
        if exe.language == "cpp":
            return ExecutableRef("no-python", cpp_sources=exe.sources, cpp_plugins=exe.plugins,
                                 cpp_linked=exe.linked)
        if self.python is None:
            return ExecutableRef("no-python")
        return self.python.get(entry_key(exe)) or ExecutableRef("no-python", entry=_entry_text(exe))


class EntryReach:
    """The nodes each Python executable of one analysis creates."""

    def __init__(self, analysis: Analysis) -> None:
        self.analysis = analysis
        self.callees: dict[tuple, set[tuple]] = {}
        for key, readers in analysis.readers.items():
            callee = key[1] if key[0] == "ret" else ("mod", key[1], ()) if key[0] == "g" else None
            if callee is None:
                continue
            for caller in readers:
                self.callees.setdefault(caller, set()).add(callee)

    def python_target(self, exe: Executable) -> ExecutableRef:
        program = self.analysis.program
        entry = _entry_text(exe)
        if exe.module is not None:
            modules = [program.modules[exe.module]] if exe.module in program.modules else []
        else:
            modules = [m for m in program.modules.values() if m.path == exe.script]
        if not modules:
            return ExecutableRef("no-python", entry=entry)
        module = modules[0]
        starts: list[tuple] = [("mod", module.name, ())]
        fids = {f.fid for f in program.functions
                if f.module is module and f.parent is None and f.cls is None
                and f.qualname == exe.function}
        starts.extend(t for t in self.analysis.effects if t[0] == "fn" and t[1] in fids)
        sites, open_sites, classes = self.node_sites(starts)
        if not sites:
            return ExecutableRef("no-python", entry=entry)
        return ExecutableRef("found", tuple(sites), tuple(open_sites), tuple(classes), entry=entry)

    def node_sites(self, starts: list[tuple]
                   ) -> tuple[list[Location], list[Location], list[tuple[Location, str | None]]]:
        """The node sites reachable from ``starts``, those open to any parameter, and the
        ``(site, class)`` of each node object created there."""
        seen = set(starts)
        queue = deque(starts)
        sites: set[Location] = set()
        open_sites: set[Location] = set()
        classes: set[tuple[Location, str | None]] = set()
        while queue:
            task = queue.popleft()
            for eff in self.analysis.effects.get(task, {}).values():
                if eff.kind != "node":
                    continue
                site = Location(eff.path, eff.line, eff.column)
                sites.add(site)
                classes.update((site, _class_name(self.analysis.program, obj))
                               for obj in eff.arg("target") if isinstance(obj, Obj))
                args = dict(eff.args)
                if args.get("allow_undeclared") is not None and \
                        args["allow_undeclared"].consts() != [False]:
                    open_sites.add(site)
                if "auto_declare" in args and args["auto_declare"].consts() != [False]:
                    open_sites.add(site)
            for callee in sorted(self.callees.get(task, ()), key=repr):
                if callee not in seen:
                    seen.add(callee)
                    queue.append(callee)
        return sorted(sites), sorted(open_sites), sorted(classes, key=repr)
