"""Reads :mod:`.usage`'s facts off a finished analysis.

From the analysis' effects (kinds declared by the stubs: ``callback``, ``spin``,
``executor_node``, ``waits_for``, ``rate``, ``parameter_use`` …), its call sites
(:mod:`..absint.callgraph`) and the library model's ``blocking`` key.
"""
from __future__ import annotations

import math
from collections import deque

from ..absint.callgraph import CallGraph, CallSite
from ..absint.engine import Analysis, Effect
from ..absint.program import Function
from ..absint.values import BoundMethod, Const, Extern, FuncAtom, Obj, Record, Seq, Value, wrapped
from .declaration_sites import written_declarations
from .model import Location
from .usage import (BlockingCall, Callback, Group, NodeParameters, OutOfOrder, ParameterUse, PeriodArgument,
                    Redeclaration, Signature, Step, UsageFacts, callback_order)

#: Effects that create an entity on their ``node``: they fail on a destroyed node.
ENTITY_EFFECTS = frozenset({"publisher", "subscription", "service", "client", "action_server",
                            "action_client", "timer", "rate", "parameter", "parameters"})
#: Tasks one callback's search for blocking calls may visit.
MAX_REACHED_TASKS = 2000
#: Executor classes whose threads run callbacks one at a time / concurrently.
SINGLE_THREADED = frozenset({"rclpy.executors.SingleThreadedExecutor"})
MULTI_THREADED = frozenset({"rclpy.executors.MultiThreadedExecutor"})
REENTRANT_GROUP = "rclpy.callback_groups.ReentrantCallbackGroup"
#: What reading or setting an undeclared parameter raises.
UNDECLARED = "rclpy.exceptions.ParameterNotDeclaredException"
EXCLUSIVE_GROUP = "rclpy.callback_groups.MutuallyExclusiveCallbackGroup"


def _loc(item: Effect | CallSite) -> Location:
    return Location(item.path, item.line, item.column)


def _obj_sites(value: Value | None) -> frozenset[str] | None:
    """The object sites a value may be; ``None`` unless every possibility is an object."""
    if value is None or value.is_top or value.is_bottom:
        return None
    sites = set()
    for atom in value:
        if not isinstance(atom, Obj):
            return None
        sites.add(atom.site)
    return frozenset(sites)


def _class_of(atom: Obj) -> str | None:
    return atom.cls.qualname if isinstance(atom.cls, Extern) else None


def _single_const(value: Value):
    consts = value.consts()
    return consts[0] if consts and len(consts) == 1 else None


class UsageBuilder:
    """Builds :class:`UsageFacts` from a finished analysis."""

    def __init__(self, analysis: Analysis, node_labels: dict[str, str],
                 shared_sites: frozenset[str] = frozenset()) -> None:
        self.analysis = analysis
        self.program = analysis.program
        self.library = analysis.library
        self.calls: CallGraph = analysis.call_graph()
        self.effects = analysis.all_effects()
        self.node_labels = node_labels
        #: Node object sites that stand for several nodes (:meth:`.GraphBuilder._shared_sites`).
        self.shared_sites = shared_sites
        self.partial_fids = self._partial_functions()
        self.entities = self._awaitable_entities()
        self.executors: dict[str, set[str]] = {}         # node site -> executor kinds
        self.node_executors: dict[str, set[str]] = {}    # node site -> executor objects

    def build(self) -> UsageFacts:
        facts = UsageFacts()
        facts.callbacks = sorted(self._callbacks(), key=callback_order)
        in_callbacks = self._reached(t for cb in facts.callbacks if cb.on_executor
                                     for t in self._tasks(cb.fid, cb.receiver))
        # In task order: distinct tasks never render alike, so ordering the (task, effects) pairs
        # by their whole text, as before, gave this same order at many times the cost.
        spinning = [eff for task, effects in sorted(self.analysis.effects.items(), key=_task_text)
                    if task not in in_callbacks for eff in effects.values()
                    if eff.kind in ("spin", "executor_node") and "node" in dict(eff.args)]
        self.executors = self._executors(spinning)
        self.node_executors = self._node_executor_objects(spinning)
        for cb in facts.callbacks:
            if cb.on_executor:
                facts.blocking.extend(self._blocking_from(cb))
        facts.nodes = self._node_parameters()
        facts.parameter_uses = self._parameter_uses()
        facts.redeclarations = self._redeclarations()
        facts.periods = self._periods()
        facts.out_of_order = self._out_of_order()
        facts.unattributed_parameters = self._unattributed_parameters()
        return facts

    # -- callbacks ---------------------------------------------------------------------
    def _futures(self) -> dict[str, frozenset[str]]:
        """Future object site -> the entity objects (clients) whose response completes it."""
        out: dict[str, set[str]] = {}
        for eff in self.effects:
            if eff.kind == "future":
                for site in _obj_sites(eff.arg("future")) or ():
                    out.setdefault(site, set()).update(_obj_sites(eff.arg("entity")) or ())
        return {k: frozenset(v) for k, v in out.items()}

    def _owner_nodes(self, eff: Effect, futures: dict[str, frozenset[str]]) -> frozenset[str]:
        """The nodes whose executor runs a callback: its ``node``, or the node of the entity
        (client, action client) it belongs to — directly or through the future it completes."""
        args = dict(eff.args)
        if "node" in args:
            return _obj_sites(eff.arg("node")) or frozenset()
        entities = _obj_sites(eff.arg("entity")) if "entity" in args else None
        if "future" in args:
            found = _obj_sites(eff.arg("future"))
            entities = frozenset().union(*(futures.get(f, frozenset()) for f in found)) \
                if found and all(f in futures for f in found) else None
        if not entities or any(e not in self.entities for e in entities):
            return frozenset()
        nodes = [self.entities[e][0] for e in sorted(entities)]
        return nodes[0] if all(n == nodes[0] for n in nodes) else frozenset()

    def _callbacks(self) -> list[Callback]:
        out: dict[tuple, Callback] = {}
        futures = self._futures()
        for eff in self.effects:
            if eff.kind != "callback":
                continue
            nodes = self._owner_nodes(eff, futures)
            passes = _counts(eff.arg("passes"))
            by_annotation = eff.arg("annotated").consts() == [True]
            returns = _single_const(eff.arg("returns"))
            on_executor = eff.arg("executor").consts() != [False]
            group = self._group(eff.arg("group"), nodes) if "group" in dict(eff.args) else None
            role = _single_const(eff.arg("role")) or "callback"
            for atom in map(wrapped, eff.arg("function")):
                if not isinstance(atom, (FuncAtom, BoundMethod)):
                    continue
                func = self.program.functions[atom.fid]
                receiver = atom.receiver if isinstance(atom, BoundMethod) else None
                tasks = self._tasks(atom.fid, receiver)
                cb = Callback(role, passes, by_annotation,
                              returns if isinstance(returns, str) else None, on_executor,
                              _loc(eff), func.qualname, _definition(func), nodes, group,
                              self._signature(func, receiver is not None),
                              any(self._may_return_none(t) for t in tasks),
                              atom.fid, receiver)
                # by definition too: a name defined twice under a condition is two functions
                out.setdefault((cb.registration, cb.function, cb.definition, cb.role, repr(receiver)), cb)
        return list(out.values())

    def _tasks(self, fid: int, receiver) -> list[tuple]:
        tasks = self.calls.tasks_of(fid)
        if receiver is None:
            return tasks
        return [t for t in tasks if t[2] and not t[2][0].is_top and receiver in set(t[2][0])]

    def _may_return_none(self, task: tuple) -> bool:
        if task in self.analysis.falls_off:
            return True
        returned = self.analysis.returns(task)
        return not returned.is_top and any(isinstance(a, Const) and a.value is None
                                           for a in returned)

    def _signature(self, func: Function, bound: bool) -> Signature | None:
        node = func.node
        if func.fid in self.partial_fids or func.is_generator:
            return None
        known = 0 if func.kind == "function" else 1  # staticmethod, classmethod
        if len(getattr(node, "decorator_list", ())) > known:
            return None  # a decorator may wrap it in another signature
        args = node.args
        positional = args.posonlyargs + args.args
        drop = 1 if bound else 0
        if len(positional) < drop:
            return None if not args.vararg else Signature(0, None, ())
        count = len(positional) - drop
        with_default = min(len(args.defaults), count)
        required_kw = tuple(a.arg for a, d in zip(args.kwonlyargs, args.kw_defaults) if d is None)
        annotated = any(a.annotation is not None for a in positional[drop:] + args.kwonlyargs)
        return Signature(count - with_default, None if args.vararg else count, required_kw,
                         annotated)

    def _partial_functions(self) -> frozenset[int]:
        """Functions ever wrapped by a library call that pre-binds arguments
        (``functools.partial``): their signature no longer says what they accept."""
        fids = set()
        for task in self.calls.tasks():
            for site in self.calls.sites(task):
                if site.callee[0] != "lib":
                    continue
                model = self._model(site.callee[1])
                if model is None or model.returns.how != "partial":
                    continue
                for atom in map(wrapped, site.arg(model.returns.data) or ()):
                    if isinstance(atom, (FuncAtom, BoundMethod)):
                        fids.add(atom.fid)
        return frozenset(fids)

    def _model(self, qualname: str):
        owner, _, name = qualname.rpartition(".")
        return self.library.functions.get(qualname) or self.library.method(owner, name)

    # -- groups and executors ----------------------------------------------------------
    def _group(self, value: Value, nodes: frozenset[str]) -> Group | None:
        atoms_ = [] if value.is_top else list(value)
        if len(atoms_) != 1:
            return None
        atom = atoms_[0]
        if isinstance(atom, Const) and atom.value is None:
            return Group(f"default@{sorted(nodes)[0]}", False) if len(nodes) == 1 else None
        if isinstance(atom, Obj):
            cls = _class_of(atom)
            reentrant = True if cls == REENTRANT_GROUP else False if cls == EXCLUSIVE_GROUP \
                else None
            return Group(atom.site, reentrant)
        return None

    def _executor_kind(self, value: Value) -> set[str]:
        if value.consts() == [None]:
            return {"single"}  # rclpy's global executor is a SingleThreadedExecutor
        kinds = set()
        for atom in ([] if value.is_top else value):
            cls = _class_of(atom) if isinstance(atom, Obj) else None
            kinds.add("single" if cls in SINGLE_THREADED else "multi" if cls in MULTI_THREADED
                      else "unknown")
        return kinds or {"unknown"}

    def _reached(self, starts) -> set[tuple]:
        """Tasks reachable through calls from ``starts`` (included)."""
        seen = set(starts)
        queue = deque(seen)
        while queue:
            for site in self.calls.sites(queue.popleft()):
                if site.callee[0] == "task" and site.callee[1] not in seen:
                    seen.add(site.callee[1])
                    queue.append(site.callee[1])
        return seen

    def _executors(self, spinning: list[Effect]) -> dict[str, set[str]]:
        """Node site -> kinds of the executors that spin it (outside callbacks)."""
        out: dict[str, set[str]] = {}
        for eff in spinning:
            for site in _obj_sites(eff.arg("node")) or ():
                out.setdefault(site, set()).update(self._executor_kind(eff.arg("executor")))
        return out

    def _node_executor_objects(self, spinning: list[Effect]) -> dict[str, set[str]]:
        """Node site -> sites of the executor objects it is added to or spun with."""
        out: dict[str, set[str]] = {}
        for eff in spinning:
            for site in _obj_sites(eff.arg("node")) or ():
                out.setdefault(site, set()).update(_obj_sites(eff.arg("executor")) or ())
        return out

    def executor_of(self, nodes: frozenset[str]) -> str:
        kinds = set()
        for site in nodes:
            kinds |= self.executors.get(site, {"unknown"})
        return kinds.pop() if len(kinds) == 1 else "unknown"

    def _awaitable_entities(self) -> dict[str, tuple[frozenset[str], Group | None]]:
        """Entity object site -> (its node sites, the group its responses run in)."""
        out: dict[str, tuple[frozenset[str], Group | None]] = {}
        for eff in self.effects:
            if eff.kind == "rate":
                nodes = _obj_sites(eff.arg("node")) or frozenset()
                for site in _obj_sites(eff.arg("object")) or ():
                    out[site] = (nodes, Group(f"rate@{site}", True))  # rclpy: own reentrant group
            elif "object" in dict(eff.args) and "group" in dict(eff.args):
                nodes = _obj_sites(eff.arg("node")) or frozenset()
                for site in _obj_sites(eff.arg("object")) or ():
                    out[site] = (nodes, self._group(eff.arg("group"), nodes))
        return out

    # -- blocking calls ----------------------------------------------------------------
    def _blocking_from(self, cb: Callback) -> list[BlockingCall]:
        """Blocking calls reachable from ``cb``: breadth first, so each has its shortest chain."""
        out = []
        start = self._tasks(cb.fid, cb.receiver)
        seen = set(start)
        queue = deque((task, ()) for task in start)
        while queue and len(seen) <= MAX_REACHED_TASKS:
            task, chain = queue.popleft()
            for site in self.calls.sites(task):
                path = chain + (site,)
                if site.callee[0] == "task":
                    callee = site.callee[1]
                    if callee not in seen:
                        seen.add(callee)
                        queue.append((callee, path))
                    continue
                model = self._model(site.callee[1])
                if model is not None and model.blocking:
                    out.append(self._blocking(cb, path, model))
        unique: dict[tuple, BlockingCall] = {}
        for found in out:
            unique.setdefault((found.steps[0].location, found.steps[-1].location), found)
        return list(unique.values())

    def _blocking(self, cb: Callback, path: tuple[CallSite, ...], model) -> BlockingCall:
        site = path[-1]
        steps = tuple(Step(_loc(s), s.text() + "()") for s in path)
        executor = self.executor_of(cb.nodes) if cb.nodes else "unknown"
        kinds = {e.kind for e in site.effects}
        if "spin" in kinds:
            return BlockingCall(cb, steps, model.blocking, "spin", None, None,
                                self._spins_callback(cb, site), executor)
        if "waits_for" in kinds:
            concurrent, same = self._wait(cb, site)
            return BlockingCall(cb, steps, model.blocking, "wait", None, concurrent, same,
                                executor)
        if model.blocks_for:
            value = site.arg(model.blocks_for)
            consts = value.consts() if value is not None and not value.soft else None
            seconds = tuple(float(c) for c in consts) if consts and all(
                isinstance(c, (int, float)) and not isinstance(c, bool) and math.isfinite(c)
                for c in consts) else None
            return BlockingCall(cb, steps, model.blocking, "sleep", seconds, None, None, executor)
        return BlockingCall(cb, steps, model.blocking, "other", None, None, None, executor)

    def _spins_callback(self, cb: Callback, site: CallSite) -> bool | None:
        spin = next(e for e in site.effects if e.kind == "spin")
        if not cb.nodes:
            return None
        if "node" in dict(spin.args):
            nodes = _obj_sites(spin.arg("node"))
            if nodes is not None and nodes & cb.nodes:
                return True
        executors = _obj_sites(spin.arg("executor"))
        if executors:
            ours = set().union(*(self.node_executors.get(n, set()) for n in cb.nodes))
            if executors & ours:
                return True
        if "node" in dict(spin.args) and _obj_sites(spin.arg("node")) is not None:
            return False
        return None if executors is None else False

    def _wait(self, cb: Callback, site: CallSite) -> tuple[bool | None, bool | None]:
        wait = next(e for e in site.effects if e.kind == "waits_for")
        sites = _obj_sites(wait.arg("entity"))
        if not sites or any(s not in self.entities for s in sites):
            return None, None
        concurrent: set[bool | None] = set()
        same: set[bool | None] = set()
        for entity in sorted(sites):
            nodes, group = self.entities[entity]
            same.add(bool(nodes & cb.nodes) if nodes and cb.nodes else None)
            if group is None or cb.group is None:
                concurrent.add(None)
            elif group.key != cb.group.key:
                concurrent.add(True)
            else:
                concurrent.add(group.reentrant)
        return (concurrent.pop() if len(concurrent) == 1 else None,
                same.pop() if len(same) == 1 else None)

    # -- parameters --------------------------------------------------------------------
    def _node_parameters(self) -> dict[str, NodeParameters]:
        allows_undeclared: dict[str, bool] = {}
        locations: dict[str, Location] = {}
        for eff in self.effects:
            if eff.kind != "node":
                continue
            allows = any(name in dict(eff.args) and eff.arg(name).consts() != [False]
                         for name in ("allow_undeclared", "auto_declare"))
            for site in _obj_sites(eff.arg("target")) or ():
                allows_undeclared[site] = allows_undeclared.get(site, False) or allows
                locations.setdefault(site, _loc(eff))
        open_ = dict(allows_undeclared)  # and, below, a node declaring a name not known
        declared: dict[str, set[str]] = {site: set() for site in open_}
        for eff in self.effects:
            if eff.kind not in ("parameter", "parameters"):
                continue
            sites = _obj_sites(eff.arg("node"))
            names = _declared_names(eff)
            for site in sites or ():
                if site not in declared:
                    continue
                if names is None:
                    open_[site] = True
                else:
                    declared[site].update(names)
        return {site: NodeParameters(site, self.node_labels.get(site, "?"), locations[site],
                                     open_[site], frozenset(declared[site]), allows_undeclared[site])
                for site in sorted(open_)}

    def _unattributed_parameters(self) -> frozenset[str]:
        """Names written at declaration calls where no declaration on a known node was
        recorded (a call not reached, or reached with an unknown node)."""
        attributed = {(eff.path, eff.line) for eff in self.effects
                      if eff.kind in ("parameter", "parameters") and _obj_sites(eff.arg("node"))}
        return frozenset(name for path, line, name in written_declarations(
            self.program.walked(), self.program.read_names) if (path, line) not in attributed)

    def _parameter_uses(self) -> list[ParameterUse]:
        handled = self._handled_uses()
        out = []
        for eff in self.effects:
            if eff.kind != "parameter_use":
                continue
            nodes = _obj_sites(eff.arg("node"))
            how = _single_const(eff.arg("how")) or ("get_parameters" if "names" in dict(eff.args)
                                                    else "get_parameter")
            out.append(ParameterUse(_loc(eff), how, _used_names(eff),
                                    tuple(sorted(nodes)) if nodes else None, _loc(eff) in handled))
        return out

    def _handled_uses(self) -> frozenset[Location]:
        """Where every run of a parameter call sits in a ``try`` that may catch
        ``ParameterNotDeclaredException``: an ``except`` clause of it or a base class of it
        (``ParameterException``, ``Exception``; a bare one), or of a class the analysis
        cannot name (``?``), in the calling body itself."""
        # rclpy's exceptions derive from ``Exception``, as every library's do.
        catching = {*self.library.mro(UNDECLARED), "builtins.Exception", "builtins.BaseException", "?"}
        handled: set[Location] = set()
        unhandled: set[Location] = set()
        for task in self.calls.tasks():
            for site in self.calls.sites(task):
                if any(eff.kind == "parameter_use" for eff in site.effects):
                    (handled if catching.intersection(site.caught) else unhandled).add(_loc(site))
        return frozenset(handled - unhandled)

    def _redeclarations(self) -> list[Redeclaration]:
        """Parameters one run of a body declares twice on the same node: two declarations
        on every normal path (outside any ``try``), directly or through calls."""
        memo: dict[tuple, dict[tuple[str, str], Location]] = {}
        out: dict[Location, Redeclaration] = {}
        for task in self.calls.tasks():
            self._always_declared(task, memo, out, set())
        return [out[k] for k in sorted(out)]

    def _always_declared(self, task, memo, out, active) -> dict[tuple[str, str], Location]:
        if task in memo:
            return memo[task]
        if task in active:
            return {}
        active.add(task)
        items: list[tuple[tuple[str, str], Location]] = []
        for site in self.calls.sites(task):
            if site.conditional or site.guarded:
                continue
            if site.callee[0] == "task":
                for key in self._always_declared(site.callee[1], memo, out, active):
                    items.append((key, _loc(site)))
                continue
            for eff in site.effects:
                if eff.kind != "parameter":
                    continue
                name = _single_const(eff.arg("name"))
                nodes = _obj_sites(eff.arg("node"))
                # "Declared again" needs one node: a site standing for several may be two of them.
                if isinstance(name, str) and nodes is not None and len(nodes) == 1 \
                        and not nodes & self.shared_sites:
                    items.append(((name, next(iter(nodes))), _loc(site)))
        first: dict[tuple[str, str], Location] = {}
        # One place declaring a name twice is a call of a union of callees (``tree.setup()`` on
        # one of two tree classes, or one function in two contexts): one of them runs, not both.
        for key, location in sorted(set(items), key=lambda i: (i[1], i[0])):
            if key in first:
                out.setdefault(location, Redeclaration(
                    location, key[0], self.node_labels.get(key[1], "?"), first[key]))
            else:
                first[key] = location
        active.discard(task)
        memo[task] = first
        return first

    # -- lifecycle order ---------------------------------------------------------------
    def _out_of_order(self) -> list[OutOfOrder]:
        """In one body: a node created before an ``rclpy.init()`` that always follows it, a node
        created after an ``rclpy.shutdown()`` that always precedes it (with no init in between),
        an entity created on a node after its ``destroy_node()``.
        Only calls on every path (outside ``try``) order a body; custom contexts are skipped."""
        memo: dict[tuple, bool] = {}
        entity_memo: dict[tuple, frozenset[str]] = {}
        made_memo: dict[tuple, frozenset[str]] = {}
        out: dict[Location, OutOfOrder] = {}
        for task in self.calls.tasks():
            sites = self.calls.sites(task)
            kinds = [{e.kind for e in s.effects} for s in sites]
            if not sites or any(_custom_context(e) for s in sites for e in s.effects):
                continue
            fixed = [not s.guarded and (not s.conditional or s.script_step) for s in sites]
            inits = [i for i, k in enumerate(kinds) if "context_init" in k and fixed[i]]
            shutdowns = [i for i, k in enumerate(kinds) if "context_shutdown" in k and fixed[i]]
            any_init = [i for i, k in enumerate(kinds) if "context_init" in k]
            for i, site in enumerate(sites):
                creates = self._creates_node(site, memo)
                if creates and fixed[i] and inits and inits[0] > i and \
                        not any(j < i for j in any_init):
                    out.setdefault(_loc(site), OutOfOrder(
                        _loc(site), "node created", "before rclpy.init()", _loc(sites[inits[0]])))
                earlier = [d for d in shutdowns if d < i and not any(d < j < i for j in any_init)]
                if creates and earlier:
                    out.setdefault(_loc(site), OutOfOrder(
                        _loc(site), "node created", "after rclpy.shutdown()",
                        _loc(sites[earlier[0]])))
            self._after_destroy(sites, fixed, out, entity_memo, made_memo)
        return [out[k] for k in sorted(out)]

    def _after_destroy(self, sites, fixed, out, memo, made_memo) -> None:
        destroyed: dict[str, int] = {}
        for i, site in enumerate(sites):
            # A node made again where the destroyed one was made (the same helper, a loop) is
            # the same abstract object but a new handle: its entities are in order.
            for node in self._nodes_made(site, made_memo) & destroyed.keys():
                del destroyed[node]
            for node in sorted(self._creates_on(site, memo) & destroyed.keys()):
                label = self.node_labels.get(node, "?")
                out.setdefault(_loc(site), OutOfOrder(
                    _loc(site), f"`{site.text()}()` creates an entity on node {label}",
                    "after its destroy_node()", _loc(sites[destroyed[node]])))
            if fixed[i]:
                for eff in site.effects:
                    nodes = _obj_sites(eff.arg("node")) if eff.kind == "node_destroy" else None
                    if nodes is not None and len(nodes) == 1:
                        destroyed.setdefault(next(iter(nodes)), i)

    def _nodes_made(self, site: CallSite, memo: dict) -> frozenset[str]:
        """The object sites of the nodes the call may make, on any path through it."""
        return self._through_calls(site, memo, _made_nodes, every_path=False)

    def _creates_on(self, site: CallSite, memo: dict) -> frozenset[str]:
        """The nodes the call creates an entity on, on every path through it."""
        return self._through_calls(site, memo, _entity_nodes, every_path=True)

    def _through_calls(self, site: CallSite, memo: dict, from_library, every_path: bool,
                       depth: int = 0) -> frozenset[str]:
        """What ``from_library`` reads off the library calls ``site`` reaches (through workspace
        calls on every path, or on any), memoised by task."""
        if site.callee[0] == "lib":
            return from_library(site)
        task = site.callee[1]
        if task not in memo:
            memo[task] = frozenset()  # recursion: nothing known
            memo[task] = frozenset().union(*(
                self._through_calls(s, memo, from_library, every_path, depth + 1)
                for s in self.calls.sites(task) if not every_path or not (s.conditional or s.guarded))) \
                if depth < 8 else frozenset()
        return memo[task]

    def _creates_node(self, site: CallSite, memo: dict, depth: int = 0) -> bool:
        """The call creates a node on every path (a modelled node constructor or factory, or
        workspace code that always calls one)."""
        if site.callee[0] == "lib":
            return any(e.kind == "node" for e in site.effects)
        task = site.callee[1]
        if task in memo:
            return memo[task]
        memo[task] = False  # recursion: not known to create
        memo[task] = depth < 8 and any(
            not s.conditional and not s.guarded and self._creates_node(s, memo, depth + 1)
            for s in self.calls.sites(task))
        return memo[task]

    # -- periods -----------------------------------------------------------------------
    def _periods(self) -> list[PeriodArgument]:
        out = []
        stopped = frozenset().union(*(_obj_sites(eff.arg("timer")) or () for eff in self.effects
                                      if eff.kind == "timer_stop"))
        for eff in self.effects:
            if eff.kind == "timer":
                value, what = eff.arg("period"), "timer period"
            elif eff.kind == "rate":
                value, what = eff.arg("frequency"), "rate frequency"
            else:
                continue
            consts = value.consts() if not value.soft else None
            timer = _obj_sites(eff.arg("object")) if eff.kind == "timer" else None
            out.append(PeriodArgument(_loc(eff), what, tuple(consts) if consts else None,
                                      eff.conditional, bool(timer and timer & stopped)))
        return out


def _made_nodes(site: CallSite) -> frozenset[str]:
    """The object sites of the nodes a library call makes."""
    return frozenset().union(*(_obj_sites(eff.arg("target")) or () for eff in site.effects
                               if eff.kind == "node"))


def _entity_nodes(site: CallSite) -> frozenset[str]:
    """The node a library call creates an entity on, when it is one known node."""
    out: set[str] = set()
    for eff in site.effects:
        nodes = _obj_sites(eff.arg("node")) if eff.kind in ENTITY_EFFECTS else None
        if nodes is not None and len(nodes) == 1:
            out |= nodes
    return frozenset(out)


def _custom_context(eff: Effect) -> bool:
    """An init/shutdown of a context other than the default one."""
    return eff.kind in ("context_init", "context_shutdown") and eff.arg("context").consts() != [None]


def _definition(func: Function) -> Location:
    node = func.node
    return Location(func.module.path, getattr(node, "lineno", 1), func.module.column(node))


def _counts(value: Value) -> tuple[int, ...] | None:
    """An argument count, or a sequence of alternative counts, as a tuple (``None``: unknown)."""
    consts = value.consts()
    if consts is not None and len(consts) == 1 and isinstance(consts[0], int):
        return (consts[0],)
    found = [a for a in value] if not value.is_top else []
    if len(found) == 1 and isinstance(found[0], Seq):
        counts = [_single_const(v) for v in found[0].items]
        if counts and all(isinstance(c, int) and not isinstance(c, bool) for c in counts):
            return tuple(counts)
    return None


def _declared_names(eff: Effect) -> list[str] | None:
    """The names a ``parameter``/``parameters`` effect declares; ``None`` if any is unknown."""
    if eff.kind == "parameter":
        return eff.arg("name").strings()
    prefixes = eff.arg("namespace").strings()
    value = eff.arg("parameters")
    if prefixes is None or value.is_top:
        return None
    names = []
    for atom in value:
        if not isinstance(atom, Seq):
            return None  # a list whose entries are not all known
        for item in atom.items:
            for entry in ([] if item.is_top else item):
                if not isinstance(entry, Seq) or not entry.items:
                    return None
                found = entry.items[0].strings()
                if found is None:
                    return None
                names += [f"{p}.{n}" if p else n for p in prefixes for n in found]
            if item.is_top:
                return None
    return names


def _used_names(eff: Effect) -> tuple[str, ...] | None:
    args = dict(eff.args)
    if "name" in args:
        found = eff.arg("name").strings()
        return tuple(found) if found and len(found) == 1 else None
    value = eff.arg("names") if "names" in args else eff.arg("parameters")
    if value.is_top or len(list(value)) != 1:
        return None
    seq = next(iter(value))
    if not isinstance(seq, Seq):
        return None
    names = []
    for item in seq.items:
        if "names" in args:
            found = item.strings()
        else:  # Parameter records: their name field
            found = None
            if not item.is_top and len(list(item)) == 1:
                rec = next(iter(item))
                field_ = rec.field("name") if isinstance(rec, Record) else None
                found = field_.strings() if field_ is not None else None
        if found is None or len(found) != 1:
            return None
        names.append(found[0])
    return tuple(names)


def build_usage(analysis: Analysis, node_labels: dict[str, str],
                shared_sites: frozenset[str] = frozenset()) -> UsageFacts:
    return UsageBuilder(analysis, node_labels, shared_sites).build()


def _task_text(item: tuple[tuple, dict]) -> str:
    return repr(item[0])
