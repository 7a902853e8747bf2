"""The fixpoint engine: tasks, the shared abstract heap, and the interprocedural worklist.

A *task* is one body analysed under one context: a module top level, or a function
with a tuple of abstract argument values (functional context sensitivity, bounded
per function by :data:`MAX_CONTEXTS`).  Within a task, local variables are
flow-sensitive (an environment per CFG block, joined at merges, widened at loop
heads).  Everything that outlives a call — object fields by allocation site, class
attributes, module globals, closure cells, stored library state, and the return
value of each task — lives in one global *heap* of monotone cells.  A task that reads
a cell is re-run when the cell grows, so the whole program reaches a joint fixpoint;
because every cell lives in a lattice of finite height, that always happens.  Budgets
bound the work anyway and turn a runaway analysis into "unknown" plus a diagnostic.

Entry points are all module top levels, then every module-level function nobody
called (library code may call it), then every callable a library model says it calls
back later, then every leaf class derived from a library class marked ``entry`` that
no analysed code instantiates.
"""
from __future__ import annotations

import ast
from collections import deque
from dataclasses import dataclass
from typing import Hashable

from .library import LibraryModel
from .program import Program
from .values import BOTTOM, TOP, Value

#: Contexts per function before further calls share one all-⊤ context.
MAX_CONTEXTS = 8
#: Block visits per task run before the run is abandoned as ⊤.
MAX_BLOCK_VISITS = 4000
#: Visits of a loop head before its environment is widened.
WIDEN_AFTER = 3
#: Growths of a heap cell holding only numbers before it is widened to ⊤.
HEAP_WIDEN_AFTER = 3

Task = tuple  # ("mod", module name, ()) | ("fn", fid, ctx)


@dataclass(frozen=True)
class Effect:
    """A modelled library call's declared effect, with its arguments evaluated."""

    kind: str
    args: tuple[tuple[str, Value], ...]
    path: str
    line: int
    column: int
    conditional: bool

    def arg(self, name: str) -> Value:
        for key, val in self.args:
            if key == name:
                return val
        return TOP


@dataclass(frozen=True)
class Diagnostic:
    path: str
    line: int
    message: str
    severity: str = "warning"  # "info" for precision given up on purpose (context bounds)


class Analysis:
    """Runs the whole-program fixpoint and keeps its results (heap, effects, diagnostics)."""

    def __init__(self, program: Program, library: LibraryModel, max_task_runs: int | None = None,
                 every_module_is_entry: bool = False):
        self.program = program
        self.library = library
        self.heap: dict[Hashable, Value] = {}
        self.readers: dict[Hashable, dict[Task, None]] = {}
        self.contexts: dict[int, dict[tuple, None]] = {}
        self._context_counts: dict[tuple, set[tuple]] = {}
        self._growth: dict[Hashable, int] = {}
        self._overflowed: set[int] = set()
        self.effects: dict[Task, dict[tuple, Effect]] = {}
        self.allocated: set[int] = set()           # cids instantiated by analysed code
        self.called: set[int] = set()              # fids with at least one task
        #: Calls evaluated at least once, as (path, line, col_offset): what ``--explain`` reads
        #: to tell a call the analysis reached from one it never got to.
        self.reached_calls: set[tuple[str, int, int]] = set()
        self.diagnostics: list[Diagnostic] = []
        self._queue: deque[Task] = deque()
        self._queued: set[Task] = set()
        self._known: set[Task] = set()
        self._exhausted = False
        size = len(program.functions) + len(program.modules)
        self.max_task_runs = max_task_runs if max_task_runs is not None else 200 + 60 * size
        self.task_runs = 0
        self.every_module_is_entry = every_module_is_entry
        self.relevant: set[str] = set()

    # -- heap -----------------------------------------------------------------------------
    def read(self, key: Hashable, task: Task) -> Value:
        self.readers.setdefault(key, {})[task] = None
        if key[0] == "g" and ("mod", key[1], ()) not in self._known:
            self.enqueue(("mod", key[1], ()))  # a module needed only for its globals
        return self.heap.get(key, BOTTOM)

    def write(self, key: Hashable, value: Value) -> None:
        if value.is_bottom:
            return
        old = self.heap.get(key, BOTTOM)
        new = old.join(value)
        if new != old:
            growth = self._growth[key] = self._growth.get(key, 0) + 1
            if growth > HEAP_WIDEN_AFTER and _numbers_only(new):
                new = TOP  # a counter (``self.count += 1``): widen instead of counting up
            self.heap[key] = new
            for reader in self.readers.get(key, ()):
                self.enqueue(reader)

    # -- tasks ----------------------------------------------------------------------------
    def enqueue(self, task: Task) -> None:
        self._known.add(task)
        if task not in self._queued:
            self._queued.add(task)
            self._queue.append(task)

    def function_task(self, fid: int, ctx: tuple) -> Task:
        """The task for calling ``fid`` with ``ctx``, registering (and bounding) contexts.

        A method's receiver is always kept, so every object is analysed as itself. The
        bound counts the distinct *other* arguments per function — per receiver for
        ``__init__``, which runs once per object, so that a fleet of nodes built from one
        class keeps every name. Past the bound the other arguments become ⊤ (and a
        diagnostic says so once): a logging helper called with a hundred messages costs
        nine analyses, not a hundred.
        """
        func = self.program.functions[fid]
        method = func.cls is not None and func.kind == "function" and len(ctx) > 0
        per_object = method and getattr(func.node, "name", "") == "__init__"
        bucket = (fid, ctx[0]) if per_object else (fid,)
        rest = ctx[1:] if method else ctx
        seen = self.contexts.setdefault(fid, {})
        counted = self._context_counts.setdefault(bucket, set())
        if ctx not in seen and rest not in counted and len(counted) >= MAX_CONTEXTS:
            ctx = ((ctx[0],) if method else ()) + tuple(TOP for _ in ctx[1 if method else 0:])
            if fid not in self._overflowed:
                self._overflowed.add(fid)
                self.diagnostics.append(Diagnostic(
                    func.module.path, getattr(func.node, "lineno", 1),
                    f"{func.qualname} is called in more than {MAX_CONTEXTS} different ways; "
                    "further calls are analysed with unknown arguments", "info"))
        seen[ctx] = None
        counted.add(ctx[1:] if method else ctx)
        self.called.add(fid)
        task = ("fn", fid, ctx)
        if task not in self._known:
            self.enqueue(task)
        return task

    def context_index(self, fid: int, ctx: tuple) -> int:
        """A stable small number for a context of ``fid`` (its order of discovery), capped
        at :data:`MAX_CONTEXTS` so that recursion through allocation (a constructor that
        builds another instance of its class) makes finitely many objects."""
        for index, known in enumerate(self.contexts.get(fid, ())):
            if known == ctx:
                return min(index, MAX_CONTEXTS)
        return 0

    def call_summary(self, fid: int, ctx: tuple, caller: Task) -> Value:
        task = self.function_task(fid, ctx)
        return self.read(("ret", task), caller)

    def run(self) -> None:
        """Analyse from every entry point until nothing changes (or the budget runs out)."""
        from .interpreter import Interpreter
        self._interp = Interpreter(self)
        self.relevant = set(self.program.modules) if self.every_module_is_entry \
            else self.relevant_modules()
        for name in sorted(self.relevant):
            if self.program.ensure(name) is not None:
                self.enqueue(("mod", name, ()))
        self._drain()
        while not self._exhausted and (self._uncalled_functions() or self._entry_classes()):
            self._drain()

    def _drain(self) -> None:
        while self._queue:
            if self.task_runs >= self.max_task_runs:
                if not self._exhausted:
                    self._exhausted = True
                    self.diagnostics.append(Diagnostic(
                        "", 0, f"analysis budget of {self.max_task_runs} task runs exhausted; "
                        "results may be incomplete"))
                self._queue.clear()
                self._queued.clear()
                return
            task = self._queue.popleft()
            self._queued.discard(task)
            self.task_runs += 1
            ret, effects = self._interp.run_task(task)
            self.effects[task] = effects
            if task[0] == "fn":
                self.write(("ret", task), ret)

    def relevant_modules(self) -> set[str]:
        """Modules that import an active library (see :meth:`LibraryModel.active_roots`), or a
        workspace module that does, transitively. Only these are entry points; other modules
        are analysed on demand when a relevant one reads their globals."""
        roots = self.library.active_roots()
        imports = self.program.imports
        relevant = {m for m, names in imports.items()
                    if any(n.split(".")[0] in roots for n in names)}
        changed = True
        while changed:
            changed = False
            for mod, names in imports.items():
                if mod not in relevant and any(
                        n in relevant or n.rpartition(".")[0] in relevant for n in names):
                    relevant.add(mod)
                    changed = True
        return relevant

    def _uncalled_functions(self) -> bool:
        """Module-level functions no analysed code calls: entries, with their defaults."""
        added = False
        for func in self.program.functions:
            if func.parent is None and func.cls is None and func.fid not in self.called \
                    and func.module.name in self.relevant and not isinstance(func.node, ast.Lambda):
                self.function_task(func.fid, self._interp.default_context(func.fid, None))
                added = True
        return added

    def _entry_classes(self) -> bool:
        """Leaf subclasses of ``entry`` library classes that nothing instantiates."""
        added = False
        bases_of = {c.cid: self._interp.user_bases(c.cid) for c in self.program.classes}
        has_sub = {b for bases in bases_of.values() for b in bases}
        for klass in self.program.classes:
            cid = klass.cid
            if cid in self.allocated or cid in has_sub:
                continue
            if any(self.library.class_flag(q, "entry") for q in self._interp.library_bases(cid)):
                self._interp.instantiate_entry(cid)
                added = True
        return added

    def schedule(self, task: Task) -> None:
        if task not in self._known:
            self.enqueue(task)

    # -- results --------------------------------------------------------------------------
    def all_effects(self) -> list[Effect]:
        """Effects of the latest run of every task, deduplicated, in a stable order."""
        seen: dict[Effect, None] = {}
        for effects in self.effects.values():
            for eff in effects.values():
                seen[eff] = None
        return sorted(seen, key=lambda e: (e.path, e.line, e.column, e.kind, repr(e.args)))


def _numbers_only(value: Value) -> bool:
    consts = value.consts()
    return bool(consts) and all(isinstance(c, (int, float)) and not isinstance(c, bool)
                                for c in consts)
