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

Several executables may run one node class (a driver class, and front ends that
each add their own ends in ``main``): the builder makes one code node of it, with
every front end's ends. An end created by code that only *another* executable of
that node class reaches (its ``main``) is not one of this executable's ends
(:attr:`~.model.ExecutableRef.foreign_end_sites`). Ends no entry point reaches
(those made in callbacks) belong to every executable of the class. Executables of one
node class run modules of one group (they all import the class), so one analysis
answers for all of them.
"""
from __future__ import annotations

import ast
from collections import deque
from typing import Mapping, Sequence

from ..absint.engine import Analysis, Effect
from ..absint.values import ClassAtom, Obj
from ..graph.builder import _class_name
from ..absint.main_guard import is_main_guard
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
    """The nodes each Python executable of one analysis creates; ``executables``: all the
    Python executables that run the analysis's modules."""

    def __init__(self, analysis: Analysis, executables: Sequence[Executable]) -> None:
        self.analysis = analysis
        self.executables = executables
        self.callees: dict[tuple, set[tuple]] = {}
        self._walks: dict[Executable, tuple | None] = {}
        self._guarded: dict[str, frozenset[int]] = {}
        self._guarded_lines: dict[str, tuple[tuple[int, int], ...]] = {}
        for key, readers in analysis.readers.items():
            callee = key[1] if key[0] == "ret" else ("mod", key[1], ()) if key[0] == "g" else None
            if callee is None:
                continue
            for caller in readers:
                self.callees.setdefault(caller, set()).add(callee)

    def python_target(self, exe: Executable) -> ExecutableRef:
        entry = _entry_text(exe)
        walked = self._walked(exe)
        if walked is None or not walked[0]:
            return ExecutableRef("no-python", entry=entry)
        sites, open_sites, classes, ends = walked
        return ExecutableRef("found", tuple(sites), tuple(open_sites), tuple(classes), entry=entry,
                             foreign_end_sites=self._foreign_ends(exe, frozenset(sites), ends))

    def _starts(self, exe: Executable) -> list[tuple] | None:
        """The analysis tasks ``exe`` starts with (its module's top level, its entry function);
        ``None`` when its code is not among the analysed modules."""
        program = self.analysis.program
        if exe.module is not None:
            modules = [program.modules[exe.module]] if exe.module in program.modules else []
        else:
            modules = [m for m in program.modules.values() if m.path == exe.script]
        if not modules:
            return None
        module = modules[0]
        starts: list[tuple] = [("mod", module.name, ())]
        fids = {f.fid for f in program.functions
                if f.module is module and f.parent is None and f.cls is None
                and f.qualname == exe.function}
        starts.extend(t for t in self.analysis.effects if t[0] == "fn" and t[1] in fids)
        return starts

    def _walked(self, exe: Executable) -> tuple | None:
        """:meth:`node_sites` from ``exe``'s start (``None``: its code is not analysed here), once."""
        if exe not in self._walks:
            starts = self._starts(exe)
            self._walks[exe] = None if starts is None else self.node_sites(starts)
        return self._walks[exe]

    def _foreign_ends(self, exe: Executable, sites: frozenset[Location],
                      ends: frozenset[Location]) -> tuple[Location, ...]:
        """End sites that other Python executables of one of ``exe``'s node ``sites`` reach and
        ``exe`` does not (its own are ``ends``)."""
        foreign: set[Location] = set()
        for other in self.executables:
            walked = self._walked(other) if other != exe else None
            if walked is not None and sites.intersection(walked[0]):
                foreign |= walked[3]
        return tuple(sorted(foreign - ends))

    def _methods_of(self, cids: set[int]) -> set[tuple]:
        """The analysed tasks of the methods of the workspace classes ``cids`` — by identity,
        not by name: a script and its copy (``scripts/x`` and ``scripts/x.py``), or two
        packages, may each define a ``Navigation`` class, and one executable runs only its own."""
        program = self.analysis.program
        fids = {f.fid for f in program.functions if f.cls is not None and f.cls in cids}
        return {task for task in self.analysis.effects if task[0] == "fn" and task[1] in fids}

    def _main_guarded(self, task: tuple) -> frozenset[int]:
        """The top-level functions of ``task``'s module, and the methods of its top-level
        classes, that its top level calls only under ``if __name__ == '__main__':`` — not run
        when another module imports it (a helper imported from another node's script does not
        start that script's node, whether its guard calls ``main()`` or ``CarouselNode()``)."""
        known = self._guarded.get(task[1])
        if known is None:
            module = self.analysis.program.modules.get(task[1])
            names = _main_guard_calls(module.tree) if module is not None else frozenset()
            known = self._guarded[task[1]] = frozenset(
                f.fid for f in self.analysis.program.functions
                if f.module is module and f.parent is None
                and (f.qualname if f.cls is None else f.qualname.split(".", 1)[0]) in names)
        return known

    def _runs_only_as_main(self, task: tuple, eff: Effect) -> bool:
        """Whether ``eff`` of module task ``task`` stands in the body of its module's
        ``if __name__ == '__main__':`` — code a module imported by another one never runs
        (a script's ``node = Node('carousel')`` there starts no node in the script that
        imports its helpers)."""
        if task[0] != "mod":
            return False
        module = self.analysis.program.modules.get(task[1])
        if module is None or eff.path != module.path:
            return False
        spans = self._guarded_lines.get(task[1])
        if spans is None:
            spans = self._guarded_lines[task[1]] = _main_guard_spans(module.tree)
        return any(first <= eff.line <= last for first, last in spans)

    def node_sites(self, starts: list[tuple]) -> tuple[list[Location], list[Location],
                                                      list[tuple[Location, str | None]], frozenset[Location]]:
        """The node sites reachable from ``starts``, those open to any parameter, the
        ``(site, class)`` of each node object created there, and the sites of the ends
        the reachable code creates."""
        seen = set(starts)
        queue = deque(starts)
        started = frozenset(starts)
        sites: set[Location] = set()
        open_sites: set[Location] = set()
        classes: set[tuple[Location, str | None]] = set()
        cids: set[int] = set()  # the node classes, by identity: two modules may name a class alike
        ends: set[Location] = set()
        entry_reached = True
        while queue or entry_reached:
            if not queue:
                # What the entry point reached is walked; the methods of the node classes it
                # creates run in this process too (as callbacks): a node they create is one of
                # its nodes. Their ends stay every executable's of the class (module docstring).
                entry_reached = False
                methods = self._methods_of(cids) - seen
                seen |= methods
                queue.extend(sorted(methods, key=repr))
                continue
            task = queue.popleft()
            imported = task not in started
            for eff in self.analysis.effects.get(task, {}).values():
                if imported and self._runs_only_as_main(task, eff):
                    continue
                if eff.kind != "node":
                    if entry_reached:
                        ends.add(Location(eff.path, eff.line, eff.column))
                    continue
                site = Location(eff.path, eff.line, eff.column)
                sites.add(site)
                objects = [obj for obj in eff.arg("target") if isinstance(obj, Obj)]
                classes.update((site, _class_name(self.analysis.program, obj)) for obj in objects)
                cids.update(obj.cls.cid for obj in objects if isinstance(obj.cls, ClassAtom))
                args = dict(eff.args)
                if args.get("allow_undeclared") is not None and \
                        args["allow_undeclared"].consts() != [False]:
                    open_sites.add(site)
                if "auto_declare" in args and args["auto_declare"].consts() != [False]:
                    open_sites.add(site)
            skipped = self._main_guarded(task) if task[0] == "mod" and task not in started else ()
            for callee in sorted(self.callees.get(task, ()), key=repr):
                if callee not in seen and not (callee[0] == "fn" and callee[1] in skipped):
                    seen.add(callee)
                    queue.append(callee)
        return sorted(sites), sorted(open_sites), sorted(classes, key=repr), frozenset(ends)


def _called_names(nodes: list[ast.stmt]) -> set[str]:
    """Plain names called in ``nodes``, outside function and class bodies."""
    found: set[str] = set()
    todo: list[ast.AST] = list(nodes)
    while todo:
        cur = todo.pop()
        if isinstance(cur, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef, ast.Lambda)):
            continue
        if isinstance(cur, ast.Call) and isinstance(cur.func, ast.Name):
            found.add(cur.func.id)
        todo.extend(ast.iter_child_nodes(cur))
    return found


def _main_guard_spans(tree: ast.Module) -> tuple[tuple[int, int], ...]:
    """The first and last lines of the body of each top-level ``__main__`` guard."""
    return tuple((stmt.body[0].lineno, stmt.body[-1].end_lineno or stmt.body[-1].lineno)
                 for stmt in tree.body if isinstance(stmt, ast.If) and is_main_guard(stmt.test))


def _main_guard_calls(tree: ast.Module) -> frozenset[str]:
    """Names the module's top level calls under a ``__main__`` guard and nowhere else."""
    guarded: list[ast.stmt] = []
    rest: list[ast.stmt] = []
    for stmt in tree.body:
        if isinstance(stmt, ast.If) and is_main_guard(stmt.test):
            guarded.extend(stmt.body)
            rest.extend(stmt.orelse)
        else:
            rest.append(stmt)
    return frozenset(_called_names(guarded) - _called_names(rest))
