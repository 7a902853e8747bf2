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

Budgets are local (see :class:`Account`): the entry points of a module share an
account charged for the task runs they cause, and an account that overspends stops
alone, however the others fare: no budget is shared, so no module can use up another
one's share.  What it still had to analyse becomes unknown — return values ⊤, the
names of entities its unfinished tasks created unknown — and one diagnostic names the
module and the function that consumed the budget.  The order of work stays one queue
for the whole program (results where nothing overspends are those of a plain
worklist).  The account is the unit a per-module cache would key on.

Tasks run in queue order, except a call's task (and a module whose names are read), which
runs on the spot when it has never run: the caller then reads a finished return value (or
the module's names, as ``import`` runs a module before its names are read) instead of ⊥,
and need not run again once it is finished (see :meth:`Analysis.run_now`).

Entry points are all module top levels, then every module-level function nobody
called (library code may call it), then every callable a library model says it calls
back later, then every leaf class derived from a library class marked ``entry`` that
no analysed code instantiates.
"""
from __future__ import annotations

import ast
import itertools
import sys
from collections import Counter, deque
from dataclasses import dataclass, field, replace
from types import MappingProxyType
from typing import Hashable, Mapping

from .callgraph import CallGraph
from .fixtures import is_test_class
from .library import LibraryModel
from .program import Program
from .values import BOTTOM, TOP, BoundMethod, ClassAtom, FuncAtom, Obj, Value

#: Contexts per function before further calls share one all-⊤ context.
MAX_CONTEXTS = 8
#: Contexts per function whose own body runs a library model with effects (a shared helper
#: that creates the entity its caller names): each context may name one more entity, so a
#: helper called from many tests keeps more of them before its names become unknown.
MAX_EFFECT_CONTEXTS = 24
#: Effects that only record how code uses objects no model describes (:mod:`.instances`).
FACT_KINDS = frozenset({"construct", "set_attribute", "get_attribute"})
#: Past :data:`MAX_CONTEXTS`, contexts per function that still keep the functions and classes
#: passed (which code runs), their other arguments ⊤.
MAX_CODE_CONTEXTS = 32
#: Task runs the entry points of one module may cause before their unfinished work becomes
#: unknown (the busiest module of navigation2 + ros2cli needs 367).
ENTRY_TASK_RUNS = 2000
#: Block visits per task run before the run is abandoned as ⊤.
MAX_BLOCK_VISITS = 4000
#: Visits of a loop head before its environment is widened.
WIDEN_AFTER = 3
#: Growths of a heap cell holding only numbers before it is widened to ⊤.
HEAP_WIDEN_AFTER = 3
#: Objects of one class whose uncalled public methods are analysed (see ``_uncalled_methods``).
MAX_OBJECTS_PER_CLASS = 2
#: Calls nested inside one another that are analysed on the spot (see :meth:`Analysis.run_now`).
MAX_NESTED_RUNS = 6

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
    #: The source text of arguments given as call arguments (``"topic" → "prefix + '/scan'"``),
    #: to name an expression the analysis could not evaluate.
    texts: tuple[tuple[str, str], ...] = ()

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


@dataclass(eq=False)
class Account:
    """The budget of one module's entry points (its top level, its functions nobody calls,
    its classes a library instantiates), charged for the task runs they cause: their own
    analysis, the calls they make, the re-runs their heap writes trigger."""

    module: str
    runs: int = 0
    #: Runs per function (fid) or module top level (name): who consumed the budget.
    spent: Counter = field(default_factory=Counter)
    exhausted: bool = False


class Analysis:
    """Runs the whole-program fixpoint and keeps its results (heap, effects, diagnostics)."""

    def __init__(self, program: Program, library: LibraryModel, max_task_runs: int | None = None,
                 every_module_is_entry: bool = False, framework_classes: Mapping[str, str] = MappingProxyType({})):
        self.program = program
        self.library = library
        #: ``module.Class`` names some framework instantiates (a plugin registry, a command
        #: line's entry points): entry points even when no analysed code instantiates them. Each
        #: maps to the base class type its registration writes (``rqt_gui_py::Plugin``), or "".
        self.framework_classes = framework_classes
        self.heap: dict[Hashable, Value] = {}
        self.readers: dict[Hashable, dict[Task, None]] = {}
        self.contexts: dict[int, dict[tuple, None]] = {}
        self._context_counts: dict[tuple, set[tuple]] = {}
        self._code_contexts: dict[tuple, set[tuple]] = {}
        self._growth: dict[Hashable, int] = {}
        self._overflowed: set[int] = set()
        #: Functions whose own body ran a library model with effects (see MAX_EFFECT_CONTEXTS).
        self._effectful: set[int] = set()
        self.effects: dict[Task, dict[tuple, Effect]] = {}
        self.calls: dict[Task, dict] = {}          # task -> its call sites (see callgraph.py)
        self.falls_off: set[Task] = set()          # tasks whose body may end without return
        self.allocated: set[int] = set()           # cids instantiated by analysed code
        #: The objects of each workspace class, by allocation site: their methods nobody calls
        #: are entry points too (the framework or the user calls them).
        self.objects: dict[int, set[Obj]] = {}
        self.called: set[int] = set()              # fids with at least one task
        #: The calls each task evaluated in its last run, as (path, line, col_offset): what
        #: ``--explain`` reads to tell a call the analysis reached from one it never got to.
        #: Per run, not accumulated: an early run reads values not yet computed (a module's
        #: constant still ⊥) and takes branches that the final run rules out.
        self.reached_calls: dict[Task, set[tuple[str, int, int]]] = {}
        self.diagnostics: list[Diagnostic] = []
        self._known: set[Task] = set()
        #: Accounts by module name; the work queue; the account each queued task is charged to.
        self.accounts: dict[str, Account] = {}
        self._queue: deque[Task] = deque()
        self._queued: dict[Task, Account] = {}
        #: The account that first queued each task; a task's re-run falls back to it.
        self._owner: dict[Task, Account] = {}
        self._current: Account | None = None
        #: The tasks running, innermost last (a call analysed on the spot runs inside its caller).
        self._running: list[Task] = []
        #: Tasks left unfinished by an exhausted account: their results are not to be trusted.
        self.abandoned: set[Task] = set()
        self._to_abandon: list[Task] = []
        #: The whole analysis ran out of budget: nothing runs any more.
        self.stopped = False
        #: The whole analysis stops here (every account still busy is stopped). By default
        #: only the accounts bound the work: a shared cap would let one module's runaway
        #: analysis starve entry points that start later (the functions nobody calls).
        #: Past every account's budget, so that an account always stops first, naming itself.
        self.max_task_runs = max_task_runs if max_task_runs is not None \
            else ENTRY_TASK_RUNS * max(1, len(program.modules)) + 1
        self.task_runs = 0
        self.every_module_is_entry = every_module_is_entry
        self.relevant: set[str] = set()
        #: ``all_effects()`` as of ``(task_runs, number abandoned)``.
        self._all_effects: tuple[tuple[int, int], list[Effect]] | None = None

    # -- heap -----------------------------------------------------------------------------
    def read(self, key: Hashable, task: Task) -> Value:
        if key[0] == "g":
            module = ("mod", key[1], ())
            if module not in self.effects:  # its top level has not run
                if module not in self._known:
                    self.enqueue(module)  # a module needed only for its globals
                # Python runs a module before anything reads its names: so does the analysis, on
                # the spot (before ``task`` reads, so its writes need not run ``task`` again),
                # unless that module is running (an import cycle) or the nesting is too deep.
                self.run_now(module)
        readers = self.readers.get(key)
        if readers is None:
            readers = self.readers[key] = {}
        readers[task] = None
        return self.heap.get(key, BOTTOM)

    def write(self, key: Hashable, value: Value) -> None:
        if value.is_bottom:
            return
        old = self.heap.get(key, BOTTOM)
        new = old.join(value)
        if new is not old and new != old:  # a join that adds nothing gives ``old`` itself
            growth = self._growth[key] = self._growth.get(key, 0) + 1
            if growth > HEAP_WIDEN_AFTER and _numbers_only(new):
                new = TOP  # a counter (``self.count += 1``): widen instead of counting up
            self.heap[key] = new
            for reader in self.readers.get(key, ()):
                self.enqueue(reader)

    # -- tasks ----------------------------------------------------------------------------
    def enqueue(self, task: Task) -> None:
        """Queue ``task`` on the account that causes it: the running task's; outside any
        task (an entry point, a re-run caused by abandoning a task), its owner's, else its
        module's."""
        self._known.add(task)
        if task in self._queued:
            return
        account = self._current or self._owner.get(task) or self._module_account(task)
        if account.exhausted or self.stopped:
            self._to_abandon.append(task)
            return
        self._owner.setdefault(task, account)
        self._queued[task] = account
        self._queue.append(task)

    def _module_account(self, task: Task) -> Account:
        """The account of the module ``task`` belongs to: all entry points of a module share it."""
        module = task[1] if task[0] == "mod" else self.program.functions[task[1]].module.name
        account = self.accounts.get(module)
        if account is None:
            account = self.accounts[module] = Account(module)
        return account

    def function_task(self, fid: int, ctx: tuple) -> Task:
        """The task for calling ``fid`` with ``ctx``, registering (and bounding) contexts.

        A method's receiver is always kept, so every object is analysed as itself. The
        bound counts the distinct *other* arguments per method and receiver — a fleet of
        nodes built from one class keeps every node's name, and every parameter a shared
        helper of the base class declares for each of them — and per function otherwise.
        Past the bound the other arguments become ⊤ (and a diagnostic says so once): a
        logging helper called with a hundred messages on one object costs nine analyses,
        not a hundred.
        """
        func = self.program.functions[fid]
        method = func.cls is not None and func.kind == "function" and len(ctx) > 0
        bucket = (fid, ctx[0]) if method else (fid,)
        rest = ctx[1:] if method else ctx
        seen = self.contexts.setdefault(fid, {})
        counted = self._context_counts.setdefault(bucket, set())
        bound = self.context_bound(fid)
        if ctx not in seen and rest not in counted and len(counted) >= bound:
            ctx = ((ctx[0],) if method else ()) + self._code_only(bucket, rest)
            if fid not in self._overflowed:
                self._overflowed.add(fid)
                self.diagnostics.append(Diagnostic(
                    func.module.path, getattr(func.node, "lineno", 1),
                    f"{func.qualname} is called in more than {bound} different ways; "
                    "further calls are analysed with unknown arguments but the functions and "
                    "classes they pass", "info"))
        seen[ctx] = None
        counted.add(ctx[1:] if method else ctx)
        self.called.add(fid)
        task = ("fn", fid, ctx)
        if task not in self._known:
            self.enqueue(task)
        return task

    def context_bound(self, fid: int) -> int:
        """How many different calls of ``fid`` keep their own arguments."""
        return MAX_EFFECT_CONTEXTS if fid in self._effectful else MAX_CONTEXTS

    def _code_only(self, bucket: tuple, rest: tuple) -> tuple:
        """``rest`` with every argument but functions and classes made ⊤: a helper that runs
        what it is given (``init_and_spin(args, PatternNode)``, ``register(cb)``) still runs
        each one, however many call it. Bounded by :data:`MAX_CODE_CONTEXTS`."""
        kept = tuple(arg if _is_code(arg) else TOP for arg in rest)
        known = self._code_contexts.setdefault(bucket, set())
        if all(arg.is_top for arg in kept) or (kept not in known and len(known) >= MAX_CODE_CONTEXTS):
            return tuple(TOP for _ in rest)
        known.add(kept)
        return kept

    def context_index(self, fid: int, ctx: tuple) -> int:
        """A stable small number for a context of ``fid`` (its order of discovery), capped
        at :data:`MAX_CONTEXTS` so that recursion through allocation (a constructor that
        builds another instance of its class) makes finitely many objects — except for a
        context that passes code (a class to build, a function to run): objects built from
        different classes must not share one site, so those keep their own number."""
        for index, known in enumerate(self.contexts.get(fid, ())):
            if known == ctx:
                if index < MAX_CONTEXTS or not any(_is_code(value) for value in ctx):
                    return min(index, MAX_CONTEXTS)
                return min(index, MAX_CONTEXTS + MAX_CODE_CONTEXTS)
        return 0

    def run(self) -> None:
        """Analyse from every entry point until nothing changes (or the budgets run out)."""
        from .interpreter import Interpreter
        self._interp = Interpreter(self)
        self.relevant = set(self.program.modules) if self.every_module_is_entry \
            else self.relevant_modules()
        for name in sorted(self.relevant):
            if self.program.ensure(name) is not None:
                self.enqueue(("mod", name, ()))
        self._drain()
        while not self.stopped and (self._uncalled_functions() or self._entry_classes()
                                    or self._uncalled_methods()):
            self._drain()

    def _drain(self) -> None:
        """Run queued tasks until none is left, stopping each account at its budget."""
        queue = self._queue
        while queue:
            if self.task_runs >= self.max_task_runs:
                self.stopped = True
                for account in dict.fromkeys(self._queued.values()):
                    self._exhaust(account, f"the workspace's budget of {self.max_task_runs} "
                                           "task runs ran out")
                return
            task = queue.popleft()
            account = self._queued.pop(task, None)
            if account is None:
                continue  # already run on the spot (see :meth:`run_now`)
            if account.runs >= ENTRY_TASK_RUNS:
                queue.appendleft(task)
                self._queued[task] = account
                self._exhaust(account, f"its budget of {ENTRY_TASK_RUNS} task runs ran out")
                continue
            self._run(task, account)

    def run_now(self, task: Task) -> None:
        """Run a call's task that is queued and has never run, before the caller reads its
        return value: it then reads the value complete instead of ⊥ and need not run again
        once the callee has run (a caller ran about once more per callee otherwise). Not a
        task already running (recursion), nor deeper than :data:`MAX_NESTED_RUNS`, nor past a
        budget: those wait in the queue."""
        account = self._queued.get(task)
        if account is None or task in self.effects or task in self._running \
                or len(self._running) >= MAX_NESTED_RUNS or self.stopped \
                or self.task_runs >= self.max_task_runs or account.runs >= ENTRY_TASK_RUNS \
                or _stack_deeper_than(sys.getrecursionlimit() // 3):
            return
        del self._queued[task]  # its place in the queue is skipped
        self._run(task, account)

    def _run(self, task: Task, account: Account) -> None:
        self.task_runs += 1
        account.runs += 1
        account.spent[task[1]] += 1
        outer, self._current = self._current, account
        self._running.append(task)
        try:
            ret, effects, calls, falls_off = self._interp.run_task(task)
        finally:
            self._running.pop()
            self._current = outer
        self.effects[task] = effects
        self.calls[task] = calls
        if task[0] == "fn" and any(e.kind not in FACT_KINDS for e in effects.values()):
            self._effectful.add(task[1])
        if falls_off:
            self.falls_off.add(task)
        else:
            self.falls_off.discard(task)
        if task[0] == "fn":
            self.write(("ret", task), ret)
        self._abandon_pending()

    def _exhaust(self, account: Account, why: str) -> None:
        """Stop ``account``: its queued tasks are abandoned, and a diagnostic says where."""
        account.exhausted = True
        mine = list(dict.fromkeys(task for task in self._queue if self._queued.get(task) is account))
        if mine:
            kept = [task for task in self._queue if task in self._queued and self._queued[task] is not account]
            self._queue.clear()
            self._queue.extend(kept)
            for task in mine:
                del self._queued[task]
        self._to_abandon.extend(mine)
        hottest, runs = min(account.spent.items(), key=lambda item: (-item[1], str(item[0])),
                            default=(account.module, 0))
        name, path, line = self._place(hottest)
        self.diagnostics.append(Diagnostic(
            path, line, f"analysis from the entry points of module {account.module} stopped: "
                        f"{why}, the most ({runs}) in {name} (line {line}); what they create may "
                        "be incomplete and its names are unknown"))
        self._abandon_pending()

    def _place(self, key: int | str) -> tuple[str, str, int]:
        """``(name, path, line)`` of a function (by fid) or a module top level (by name)."""
        if isinstance(key, int):
            func = self.program.functions[key]
            return func.qualname, func.module.path, getattr(func.node, "lineno", 1)
        module = self.program.modules[key]
        return f"module {key}", module.path, 1

    def _abandon_pending(self) -> None:
        """Tasks an exhausted account still had to (re-)run: their return values become ⊤
        (callers elsewhere must not take a partial summary for a complete one)."""
        while self._to_abandon:
            task = self._to_abandon.pop()
            if task in self.abandoned:
                continue
            self.abandoned.add(task)
            if task[0] == "fn":
                self.write(("ret", task), TOP)  # readers re-run on their own accounts

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
        """Module-level functions no analysed code calls: entries, with their defaults.
        Those whose name some code reads wait until no other is left: what calls them (a
        ``main`` calling ``run('talker')``) may be such an entry and pass the real
        arguments, which their defaults (or unknowns) must not join."""
        uncalled = [func for func in self.program.functions
                    if func.parent is None and func.cls is None and func.fid not in self.called
                    and func.module.name in self.relevant and not isinstance(func.node, ast.Lambda)]
        first = [func for func in uncalled if func.node.name not in self.program.read_names] or uncalled
        for func in first:
            for ctx in self._interp.entry_contexts(func.fid):
                self.function_task(func.fid, ctx)
        return bool(first)

    def _entry_classes(self) -> bool:
        """Leaf subclasses of ``entry`` library classes, the classes frameworks instantiate,
        and pytest's test classes, that no analysed code instantiates."""
        added = False
        bases_of = {c.cid: self._interp.user_bases(c.cid) for c in self.program.classes}
        has_sub = {b for bases in bases_of.values() for b in bases}
        for klass in self.program.classes:
            cid = klass.cid
            if cid in self.allocated:
                continue
            registered = klass.parent is None and f"{klass.module.name}.{klass.qualname}" in self.framework_classes
            if registered or is_test_class(klass) or (cid not in has_sub and any(
                    self.library.class_flag(q, "entry") for q in self._interp.library_bases(cid))):
                self._interp.instantiate_entry(cid)
                added = True
        return added

    def _uncalled_methods(self) -> bool:
        """Public methods of analysed objects that no analysed code calls, with unknown
        arguments: a framework, a command line or another program calls them (a plugin's
        ``main(args)``, a client's ``arm()``). Never with their defaults, which the real
        caller may not use. The first :data:`MAX_OBJECTS_PER_CLASS` objects of a class
        (by allocation site) stand for all of them."""
        added = False
        for cid in sorted(self.objects):
            names = {name for base in [cid, *self._interp.user_bases(cid)]
                     for name in self.program.classes[base].methods if not name.startswith("_")}
            for obj in sorted(self.objects[cid], key=lambda o: o.site)[:MAX_OBJECTS_PER_CLASS]:
                added |= self._interp.call_uncalled(obj, sorted(names))
        return added

    def schedule(self, task: Task) -> None:
        if task not in self._known:
            self.enqueue(task)

    def close(self) -> None:
        """Drop the interpreter: it and the analysis refer to each other, a cycle that would
        keep every analysis object alive until the garbage collector finds it."""
        self._interp = None

    # -- results --------------------------------------------------------------------------
    def call_graph(self) -> CallGraph:
        """The calls each task made on its latest run."""
        return CallGraph(self.calls)

    def returns(self, task: Task) -> Value:
        """What a function task's ``return`` statements may return (falling off the end of
        the body, see :attr:`falls_off`, is not included: ⊥ when no return runs)."""
        return self.heap.get(("ret", task), BOTTOM)

    def all_effects(self) -> list[Effect]:
        """Effects of the latest run of every task, deduplicated, in a stable order.

        The effects of an abandoned task come from a run on inputs that were still
        growing: their names may be a part of the real ones, so they become unknown.
        Kept until a task runs or is abandoned again (the graph and its facts each ask)."""
        state = (self.task_runs, len(self.abandoned))
        if self._all_effects is not None and self._all_effects[0] == state:
            return list(self._all_effects[1])
        seen: dict[Effect, None] = {}
        for task, effects in self.effects.items():
            unfinished = task in self.abandoned
            for eff in effects.values():
                seen[_with_unknown_names(eff) if unfinished else eff] = None
        # Sorted by place and kind; only effects tied on those are ordered by their arguments'
        # text (the same order as sorting everything by it, without its cost).
        out: list[Effect] = []
        for _, tied in itertools.groupby(sorted(seen, key=_place_and_kind), key=_place_and_kind):
            group = list(tied)
            out += group if len(group) == 1 else sorted(group, key=lambda e: repr(e.args))
        self._all_effects = (state, out)
        return list(out)


def _stack_deeper_than(frames: int) -> bool:
    """Whether Python's stack holds more than ``frames`` frames: a task run on the spot nests
    inside its caller's, and deeply nested code must keep the depth it gets when run alone."""
    try:
        sys._getframe(frames)
    except ValueError:
        return False
    return True


def _place_and_kind(effect: Effect) -> tuple[str, int, int, str]:
    return effect.path, effect.line, effect.column, effect.kind


def _with_unknown_names(effect: Effect) -> Effect:
    """``effect`` with every argument made only of constants (names, types, periods) ⊤,
    hints included; the objects it acts on (the node, the target) stay known."""
    return replace(effect, args=tuple((key, TOP if value.consts() is not None or value.hints else value)
                                      for key, value in effect.args))


def _numbers_only(value: Value) -> bool:
    consts = value.consts()
    return bool(consts) and all(isinstance(c, (int, float)) and not isinstance(c, bool)
                                for c in consts)


def _is_code(value: Value) -> bool:
    """Whether ``value`` is only user functions, bound methods and classes (what code runs)."""
    return bool(value.atoms) and all(isinstance(a, (FuncAtom, BoundMethod, ClassAtom)) for a in value.atoms)
