"""Transfer functions: what each Python statement does to abstract values.

:class:`Interpreter` runs one task's CFG to a local fixpoint (environments per block,
joined at merges, widened at loop heads) and executes statements and bindings with
Python's scoping rules.  It is assembled from three mixins: expression evaluation
(:mod:`.expressions`), attributes and classes (:mod:`.objects`) and calls to user
code, library models and builtins (:mod:`.calls`).  Anything it cannot follow
becomes ⊤ — never an exception.
"""
from __future__ import annotations

import ast
import builtins
import heapq
from typing import Callable

from .cfg import CFG, Bind, Eval, Return
from .engine import MAX_BLOCK_VISITS, WIDEN_AFTER, Analysis, Task
from .frame import Env, Frame
from .program import Module
from .rows import LoopRows, rows_of
from .values import (BOTTOM, MAX_ATOMS, TOP, ClassAtom, Coll, Const, DictAtom, Extern, FuncAtom,
                     ModuleAtom, Obj, Record, Seq, Value, atoms, const, join_all)
from .attrflow import AttributeFlow, join_remembered, key as attribute_key
from .calls import CallSemantics
from .containers import may_be_filled_elsewhere, with_item
from .exclusion import narrow, ruled_out
from .expressions import ExpressionSemantics
from .fieldclasses import Field
from .fixtures import Fixtures
from .instances import InstanceFacts
from .objects import ObjectSemantics
from .typetests import isinstance_value

BUILTIN_NAMES = frozenset(dir(builtins))
#: Expressions whose evaluation may change state (see ``Interpreter._writes_nothing``).
_IMPURE_IN_TESTS = (ast.Call, ast.NamedExpr, ast.Await, ast.Yield, ast.YieldFrom, ast.Lambda,
                    ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)


class Interpreter(ExpressionSemantics, ObjectSemantics, CallSemantics, InstanceFacts, AttributeFlow):
    #: Statement type → its ``s_`` method (``None``: nothing to do), looked up once per type.
    _executors: dict[type, Callable | None] = {}

    def __init__(self, analysis: Analysis) -> None:
        self.an = analysis
        self.program = analysis.program
        self.lib = analysis.library
        self.frame: Frame | None = None
        self._mro_memo: dict[int, tuple[list, tuple]] = {}
        self._extern_mro: dict[str, list] = {}  # library class -> its MRO as Extern atoms
        self._own_fields: dict[int, list[Field]] = {}  # cid -> its body's fields (fieldclasses.py)
        #: Every name the class bodies walked so far annotate, and how many classes that is:
        #: only those names can be fields (a cheap first test, see ``is_annotated``).
        self._annotated: set[str] = set()
        self._annotated_upto = 0
        self._pure_tests: dict[int, bool] = {}  # id(expression) -> see ``_writes_nothing``
        self._probes: dict[int, frozenset[str]] = {}  # id(function body) -> names it probes
        #: (id(call node), id(model), receiver absent) -> argument texts (see ``apply_model``)
        self._texts: dict[tuple[int, int, bool], dict[str, str]] = {}
        self.fixtures = Fixtures(self.program)

    # =====================================================================================
    # tasks and CFGs
    # =====================================================================================
    def run_task(self, task: Task) -> tuple[Value, dict, dict, bool]:
        self.an.reached_calls[task] = set()  # what an earlier run reached no longer counts
        if task[0] == "mod":
            module = self.program.ensure(task[1])
            if module is None:  # too deeply nested to walk: reported by the program
                return BOTTOM, {}, {}, False
            frame = Frame(task, module)
            env: Env = {}
        else:
            func = self.program.functions[task[1]]
            frame = Frame(task, func.module, func)
            env = dict(zip(self.param_names(func), task[2]))
            for name, fixture in self.fixtures.arguments(func).items():
                if env[name].is_top:
                    env[name] = self.fixture_value(fixture, task)
                    if env[name].is_bottom:
                        return BOTTOM, {}, {}, False  # pytest runs it once the fixture is set up
            request = self.fixtures.request(func) if env.get("request", BOTTOM).is_top else None
            if request is not None:
                env["request"] = request
            for name in func.cellvars & env.keys():
                self.an.write(("c", func.fid, name), env[name])
        outer, self.frame = self.frame, frame
        try:
            self.run_cfg(self._cfg_of(frame), env)
            ret = frame.ret
        except RecursionError:
            # Statements or expressions nested deeper than a recursive walk can follow.
            self._diag(frame, f"{self._scope_name(frame)} is nested too deeply to analyse; "
                              "its results are unknown")
            ret = TOP
        finally:
            self.frame = outer
        if frame.func is not None and frame.func.is_generator:
            ret = TOP
        return ret, frame.effects, frame.calls, frame.falls_off

    def fixture_value(self, fid: int, reader: Task) -> Value:
        """What pytest passes for the fixture function ``fid``: what it yields (a generator)
        or returns, in the task pytest runs it in (its own fixtures bound the same way).
        Nothing (⊥) until that task has produced it: ``reader`` waits, as pytest runs no
        test whose fixture is not set up, and re-runs once the value exists (running it with
        an unknown value first would spend the contexts of the helpers it calls); unknown if
        the budget abandoned that task."""
        func = self.program.functions[fid]
        task = self.an.function_task(fid, self.default_context(fid, None))
        self.an.schedule(task)
        value = self.an.read(("yield", fid) if func.is_generator else ("ret", task), reader)
        return TOP if value.is_bottom and task in self.an.abandoned else value

    @staticmethod
    def _cfg_of(frame: Frame) -> CFG:
        if frame.func is not None:
            return frame.func.cfg
        if frame.module.cfg is None:
            from .cfg import build_cfg
            frame.module.cfg = build_cfg(frame.module.tree.body)
        return frame.module.cfg

    def not_followed(self, node: ast.AST, message: str) -> None:
        """A diagnostic at ``node``: Python the analysis does not follow (``exec``, a
        metaclass of the workspace), so what it would create is missing."""
        from .engine import Diagnostic
        self.an.diagnostics.append(Diagnostic(self.frame.module.path, getattr(node, "lineno", 1),
                                              message))

    def _diag(self, frame: Frame, message: str) -> None:
        from .engine import Diagnostic
        node = frame.func.node if frame.func else None
        self.an.diagnostics.append(Diagnostic(frame.module.path, getattr(node, "lineno", 1),
                                              message))

    def run_cfg(self, cfg: CFG, env: Env) -> None:
        frame = self.frame
        frame.dominators = cfg.exit_dominators() if cfg.exit is not None else frozenset()
        states: dict[int, Env] = {cfg.entry: env}
        visits: dict[int, int] = {}
        work = [cfg.entry]
        queued = {cfg.entry}
        budget = 0
        while work:
            bid = heapq.heappop(work)
            queued.discard(bid)
            budget += 1
            if budget > MAX_BLOCK_VISITS:
                self._diag(frame, f"analysis of {self._scope_name(frame)} stopped after "
                                  f"{MAX_BLOCK_VISITS} block visits; its results are partial")
                frame.ret = TOP
                return
            block = cfg.blocks[bid]
            frame.block = bid
            frame.guarded = bool(block.exc_succs)
            frame.catching = block.catching
            frame.env = dict(states[bid])
            tested: tuple[ast.expr, Value] | None = None
            for op in block.ops:
                if type(op) is Eval and op is block.ops[-1] and self._pure_test(op.expr):
                    tested = (op.expr, self.eval(op.expr))
                else:
                    self.exec_op(op)
            out = frame.env
            targets: list[tuple[int, Env]] = []
            for edge in block.succs:
                if edge.test is not None:
                    # A branch block ends by evaluating its test; a test without calls or
                    # assignments gives that same value again on each edge: reused.
                    value = tested[1] if tested is not None and tested[0] is edge.test \
                        else self.eval(edge.test)
                    decided = self.truth(value, by_default=False)
                    if decided is not None and decided != edge.polarity:
                        continue
                    targets.append((edge.target, self._narrowed(out, edge, block, cfg)))
                    continue
                targets.append((edge.target, out))
            for handler in block.exc_succs:
                targets.append((handler, states[bid]))
                targets.append((handler, out))
            if cfg.exit in (t for t, _ in targets) and not (block.ops and isinstance(block.ops[-1], Return)):
                frame.falls_off = True
            for target, state in targets:
                old = states.get(target)
                if old is None:
                    # Shared, not copied: a block's environments are never changed in place
                    # (a visit works on a copy, joins build new ones).
                    new = state
                else:
                    widen = target in cfg.loop_heads and visits.get(target, 0) >= WIDEN_AFTER
                    new = _join_env(old, state, widen)
                    if new == old:
                        continue
                states[target] = new
                visits[target] = visits.get(target, 0) + 1
                if target not in queued:
                    queued.add(target)
                    heapq.heappush(work, target)

    def _narrowed(self, env: Env, edge, block, cfg: CFG) -> Env:
        """``env`` on one way out of a test: without the constants the test rules out there
        (:meth:`_without_ruled_out`, every test); and past a guard that holds a local to known
        texts or numbers, only those: after ``if x not in ALLOWED: raise`` (or ``return``) ``x``
        is one of the constants ``ALLOWED`` lists, after ``if x != 'a': return`` it is ``'a'``.
        The latter only where the other way out of the test leaves the function: a branch
        that joins the rest again would mix the narrowed value with the original there and
        give it names it does not decide. Not a setting from outside either (its origin
        names it for a launch file)."""
        test = edge.test
        if self._writes_nothing(test) or self._type_test(test) is not None:
            env = self._without_ruled_out(env, test, edge.polarity)
        if not (isinstance(test, ast.Compare) and len(test.ops) == 1
                and isinstance(test.left, ast.Name) and test.left.id in env
                and self._writes_nothing(test)):
            return env
        if any(other is not edge and any(e.target != cfg.exit for e in cfg.blocks[other.target].succs)
               for other in block.succs):
            return env
        op = type(test.ops[0])
        holds = edge.polarity if op in (ast.In, ast.Eq) else \
            not edge.polarity if op in (ast.NotIn, ast.NotEq) else None
        if not holds:
            return env
        right = self.eval(test.comparators[0])
        listed = _listed_constants(right) if op in (ast.In, ast.NotIn) else right.consts()
        current = env[test.left.id]
        if not listed or current.origin is not None or (
                current.consts() is not None and set(current.consts()) <= set(listed)):
            return env
        # An overridable default (argparse's ``None`` for a required argument) is only one
        # of the values: past the guard the value is any constant the guard lists.
        known = None if current.soft else current.consts()
        kept = [c for c in listed if known is None or c in known]
        if not kept:
            return env
        narrowed = dict(env)
        narrowed[test.left.id] = atoms((Const.of(c) for c in kept), current.soft)
        return narrowed

    def _without_ruled_out(self, env: Env, test: ast.expr, holds: bool) -> Env:
        """``env`` without the constants a local cannot be when ``test`` evaluates to ``holds``
        (:mod:`.exclusion`): the ``else`` of ``if x == ''``, the body of ``if ns:``."""
        return narrow([env], self._ruled_out(test, holds), self.frame.narrowed)[0]

    def _ruled_out(self, test: ast.expr, holds: bool) -> list:
        return ruled_out(test, holds, self.eval, _listed_constants, self._slot, self._type_test)

    def _type_test(self, test: ast.expr):
        """``isinstance(x, C)`` with the builtin, ``x`` an entry :meth:`_slot` names and ``C``
        written without a call: the entry, and per atom whether it passes (``None``: not
        known); else ``None``."""
        if not (isinstance(test, ast.Call) and len(test.args) == 2 and self._writes_nothing(test.args[1])):
            return None
        name = self._slot(test.args[0])
        if name is None or not self.builtin_call(test, "isinstance", 2):
            return None
        classes = self.eval(test.args[1])
        return name, lambda atom: self.truth(isinstance_value(atoms([atom]), classes, self.lib.ancestors))

    def _slot(self, expr: ast.expr) -> str | None:
        """The environment entry ``expr`` reads: a local, or an attribute this function
        remembers storing (``self.ns`` right after ``self.ns = …``, :mod:`.attrflow`)."""
        if isinstance(expr, ast.Name):
            return expr.id
        if isinstance(expr, ast.Attribute) and self.remembered_attribute(expr) is not None:
            return attribute_key(expr.value.id, expr.attr)  # remembered: ``expr.value`` is a name
        return None

    def _pure_test(self, test: ast.expr) -> bool:
        """Whether a branch's test may be evaluated once for all its edges (a shortcut: it
        gives what evaluating it again on each edge gives): when it writes nothing."""
        return self._writes_nothing(test)

    def _writes_nothing(self, expr: ast.expr) -> bool:
        """Whether evaluating ``expr`` changes nothing its evaluation reads: no call (a library
        model may store what a later part reads, a container method mutates), no assignment,
        no ``await``/``yield``; so evaluating it again right after gives the same value."""
        pure = self._pure_tests.get(id(expr))
        if pure is None:
            pure = self._pure_tests[id(expr)] = not any(
                isinstance(node, _IMPURE_IN_TESTS) for node in ast.walk(expr))
        return pure

    @staticmethod
    def _scope_name(frame: Frame) -> str:
        return frame.func.qualname if frame.func else f"module {frame.module.name}"

    # =====================================================================================
    # statements
    # =====================================================================================
    def exec_op(self, op) -> None:
        kind = type(op)
        if kind is Eval:
            self.eval(op.expr)
        elif kind is Bind:
            self.exec_bind(op)
        elif kind is Return:
            value = const(None) if op.value is None else self.eval(op.value)
            self.frame.ret = self.frame.ret.join(value)
        else:
            try:
                method = self._executors[kind]
            except KeyError:
                method = self._executors[kind] = getattr(type(self), "s_" + kind.__name__, None)
            if method is not None:
                method(self, op)

    def exec_bind(self, op: Bind) -> None:
        if op.how == "iter":
            iterable = self.eval(op.value)
            self.assign(op.target, self.iter_elem(iterable))
            self._keep_rows(op, iterable)
        elif op.how == "enter":
            ctx = self.eval(op.value)
            self.assign(op.target, self.call_method(ctx, "__enter__", [], op.value))
        elif op.how == "except":
            if op.value is not None:
                self.eval(op.value)
            self.assign(op.target, TOP)
        else:  # match captures
            self._match_bind(op.target, self.eval(op.value))

    def _match_bind(self, pattern: ast.pattern, subject: Value) -> None:
        """Bind the names a ``case`` pattern captures to the parts of ``subject`` they match:
        ``x`` or ``P as x`` the subject, ``Cls(topic=t)`` its attribute, ``{'topic': t}`` the
        dict's item, ``[a, b]`` the items of a sequence of that length; anything else (an
        alternative, a ``*rest``, a positional class pattern) unknown."""
        if isinstance(pattern, ast.MatchAs):
            if pattern.name is not None:
                self.store_name(pattern.name, subject)
            if pattern.pattern is not None:
                self._match_bind(pattern.pattern, subject)
        elif isinstance(pattern, ast.MatchClass):
            for sub in pattern.patterns:
                self._match_bind(sub, TOP)
            matching = self._instances_of(subject, self.eval(pattern.cls))
            for attr, sub in zip(pattern.kwd_attrs, pattern.kwd_patterns):
                self._match_bind(sub, TOP if matching.is_top else self.load_attr(matching, attr))
        elif isinstance(pattern, ast.MatchMapping):
            for key, sub in zip(pattern.keys, pattern.patterns):
                self._match_bind(sub, self._match_item(subject, self.eval(key)))
            if pattern.rest is not None:
                self.store_name(pattern.rest, TOP)
        elif isinstance(pattern, ast.MatchSequence):
            items = _listed_items(subject, len(pattern.patterns))
            for i, sub in enumerate(pattern.patterns):
                self._match_bind(sub, items[i] if items is not None else TOP)
        else:  # MatchOr, MatchStar, MatchValue, MatchSingleton
            for node in ast.walk(pattern):
                name = getattr(node, "name", None)
                if isinstance(name, str):
                    self.store_name(name, TOP)

    def _instances_of(self, subject: Value, cls: Value) -> Value:
        """The possibilities of ``subject`` a class pattern of ``cls`` may match (not those
        that are certainly of another class: a workspace class's instance matches a workspace
        class in its MRO only); unknown unless some are."""
        if subject.is_top or cls.is_top:
            return TOP
        kept = []
        for atom in subject:
            if isinstance(atom, Obj) and isinstance(atom.cls, ClassAtom) and len(cls.atoms) == 1 \
                    and isinstance(next(iter(cls.atoms)), ClassAtom):
                if next(iter(cls.atoms)) in self.mro(atom.cls):
                    kept.append(atom)
            elif isinstance_value(atoms([atom]), cls, self.lib.ancestors) != const(False):
                kept.append(atom)
        return atoms(kept) if kept else TOP

    def _match_item(self, subject: Value, key: Value) -> Value:
        if subject.is_top or not all(isinstance(a, DictAtom) for a in subject):
            return TOP
        return self.e_subscript_value(subject, key)

    def _keep_rows(self, op: Bind, iterable: Value) -> None:
        """Keep the rows of a loop over a written-out table beside the joined binding, for
        the creation calls of its body (:mod:`.rows`); forget them when there are none."""
        frame = self.frame
        found = rows_of(op.target, iterable) if frame.cls is None else None
        if found is None or not all(name in frame.env for name in found[0]):
            frame.loop_rows.pop(id(op), None)
            return
        names, rows = found
        frame.loop_rows[id(op)] = LoopRows(names, tuple(frame.env[n] for n in names), rows)

    def s_Assign(self, op: ast.Assign) -> None:
        value = self.eval(op.value)
        for target in op.targets:
            self.assign(target, value)

    def s_AugAssign(self, op: ast.AugAssign) -> None:
        current = self.eval(_as_load(op.target))
        self.assign(op.target, self.binop(op.op, current, self.eval(op.value)))

    def s_AnnAssign(self, op: ast.AnnAssign) -> None:
        if op.value is not None:
            self.assign(op.target, self.eval(op.value))

    def s_Expr(self, op: ast.Expr) -> None:
        self.eval(op.value)

    def s_Delete(self, op: ast.Delete) -> None:
        for target in op.targets:
            if isinstance(target, ast.Name) and self.frame.func is not None \
                    and target.id in self.frame.func.locals:
                self.frame.env.pop(target.id, None)
                self.forget_variable(target.id)
            elif isinstance(target, ast.Attribute):
                self.forget_attributes()

    def s_Import(self, op: ast.Import) -> None:
        for alias in op.names:
            if alias.asname:
                self.store_name(alias.asname, self.module_value(
                    self.program.absolute_import(self.frame.module, alias.name)))
            else:
                top = alias.name.split(".")[0]
                self.store_name(top, self.module_value(
                    self.program.absolute_import(self.frame.module, top)))

    def s_ImportFrom(self, op: ast.ImportFrom) -> None:
        base = self.program.resolve_import(self.frame.module, op.module, op.level)
        for alias in op.names:
            if alias.name == "*":
                self._star_import(base)
                continue
            self.store_name(alias.asname or alias.name, self.import_member(base, alias.name))

    def _star_import(self, base: str) -> None:
        """``from base import *``: the names of ``__all__`` when the module defines it (read
        from the heap: this task re-runs when it grows), else its public globals."""
        module = self.program.ensure(base)
        if module is None:
            return  # names from a library star import stay unknown (⊤ on lookup)
        names = [n for n in module.globals | self.program.star_names(module)
                 if not n.startswith("_")]
        if "__all__" in module.globals:
            listed = self.load_global(module, "__all__")
            if listed.is_bottom:
                return  # not computed yet
            strings = self.iter_elem(listed).strings()
            if strings:
                names = list(strings)
        for name in sorted(set(names)):
            value = self.import_member(base, name)
            if not value.is_bottom:  # a candidate the source never binds (yet) binds nothing
                self.store_name(name, value)

    def s_FunctionDef(self, op: ast.FunctionDef) -> None:
        for dec in op.decorator_list:
            self.eval(dec)
        fid = self.program.fid_of[id(op)]
        self.store_name(op.name, atoms([FuncAtom(fid)]))

    s_AsyncFunctionDef = s_FunctionDef

    def s_ClassDef(self, op: ast.ClassDef) -> None:
        cid = self.program.cid_of[id(op)]
        klass = self.program.classes[cid]
        bases = tuple(self.eval(b) for b in op.bases) or (atoms([Extern("builtins.object")]),)
        for kw in op.keywords:
            value = self.eval(kw.value)
            if kw.arg == "metaclass" and any(isinstance(a, ClassAtom) for a in value):
                self.not_followed(op, f"the metaclass of {klass.qualname} is not followed: its "
                                      "instances are analysed as if the class were built by type")
        self.an.write(("bases", cid), atoms([Seq("tuple", bases)]))
        outer = self.frame
        inner = Frame(outer.task, outer.module, outer.func, klass, effects=outer.effects,
                      calls=outer.calls)
        self.frame = inner
        try:
            self.run_cfg(klass.cfg, {})
        finally:
            self.frame = outer
        self.store_name(op.name, atoms([ClassAtom(cid)]))

    # -- binding ----------------------------------------------------------------------------
    def assign(self, target: ast.AST, value: Value) -> None:
        if isinstance(target, ast.Name):
            self.store_name(target.id, value)
        elif isinstance(target, ast.Attribute):
            holder = self.eval(target.value)
            self.store_attr(holder, target.attr, value)
            self.record_attribute_store(target, holder, value)
            self.remember_attribute(target, holder, value)
            if isinstance(target.value, (ast.Name, ast.Attribute)) \
                    and any(isinstance(a, Record) for a in holder):
                # Records (library value objects such as a QoS profile) are updated in place
                # through the variable or attribute (``self.qos.depth = 5``) that holds them.
                self.assign(target.value, _with_field(holder, target.attr, value))
        elif isinstance(target, ast.Subscript):
            holder = self.eval(target.value)
            key = self.eval(target.slice)
            if isinstance(target.value, (ast.Name, ast.Attribute)) \
                    and any(isinstance(a, (Seq, Coll, DictAtom)) for a in holder):
                self.assign(target.value, with_item(holder, key, value))
        elif isinstance(target, (ast.Tuple, ast.List)):
            self._assign_seq(target.elts, value)
        elif isinstance(target, ast.Starred):
            self.assign(target.value, TOP)

    def _assign_seq(self, elts: list[ast.expr], value: Value) -> None:
        n = len(elts)
        parts: list[Value] = [BOTTOM] * n
        if value.is_top or any(isinstance(e, ast.Starred) for e in elts):
            parts = [TOP] * n
        else:
            for atom in value:
                if isinstance(atom, Seq) and len(atom.items) == n:
                    parts = [p.join(v) for p, v in zip(parts, atom.items)]
                else:
                    elem = self.iter_elem(atoms([atom]))
                    parts = [p.join(elem) for p in parts]
        for elt, part in zip(elts, parts):
            self.assign(elt, part)

    def store_name(self, name: str, value: Value) -> None:
        frame = self.frame
        if frame.comp and name in frame.comp[-1]:
            frame.comp[-1][name] = value
            return
        if frame.cls is not None:
            frame.env[name] = value
            self.an.write(("k", frame.cls.cid, name), value)
            return
        func = frame.func
        if func is None:
            frame.env[name] = value
            self.an.write(("g", frame.module.name, name), value)
            return
        if name in func.global_decl:
            self.an.write(("g", frame.module.name, name), value)
        elif name in func.nonlocal_decl:
            owner = self.program.closure_owner(func.fid, name)
            if owner is not None:
                self.an.write(("c", owner, name), value)
        else:
            frame.env[name] = value
            self.forget_variable(name)
            if name in func.cellvars:
                self.an.write(("c", func.fid, name), value)

    def load_name(self, name: str) -> Value:
        frame = self.frame
        if name.startswith("$"):  # the CFG's temporaries (a loop's iterable, a match subject)
            return frame.env.get(name, TOP)
        if frame.comp:
            for overlay in reversed(frame.comp):
                if name in overlay:
                    return overlay[name]
        if frame.cls is not None and name in frame.env:
            return frame.env[name]
        func = frame.func
        if func is None and frame.cls is None:
            if name in frame.env:
                return frame.env[name]
            return self.load_global(frame.module, name)
        if func is not None:
            if (name in func.locals or name.startswith("$")) and frame.cls is None:
                # ``$tN`` are the CFG's own temporaries (a for loop's iterable): always local
                return frame.env.get(name, BOTTOM)
            if name not in func.global_decl:
                owner = func.fid if name in func.locals else \
                    self.program.closure_owner(func.fid, name)
                if owner is not None:
                    return self.an.read(("c", owner, name), frame.task)
            if name == "__class__":
                return self._defining_class(func)
        return self.load_global(frame.module, name)

    def _defining_class(self, func) -> Value:
        """``__class__`` in a method (or a function nested in one): the class whose body
        defines the method — the implicit cell ``super()`` uses, whatever ``self`` is."""
        while func is not None and func.cls is None:
            func = self.program.functions[func.parent] if func.parent is not None else None
        return atoms([ClassAtom(func.cls)]) if func is not None else TOP

    def load_global(self, module: Module, name: str) -> Value:
        self.program.ensure(module.name)
        if name in module.globals or name in self.program.star_names(module):
            return self.an.read(("g", module.name, name), self.frame.task)
        if name == "__name__":
            return TOP
        if name in BUILTIN_NAMES:
            return atoms([Extern("builtins." + name)])
        return self._from_library_star(module, name)

    def _from_library_star(self, module: Module, name: str) -> Value:
        """A name the module never binds, read where its ``from … import *`` of library modules
        is what can bind it: that module's member when there is one such import, or the
        members of each when they are sibling modules of one package (``from arm_msgs.msg
        import *`` and ``from arm_msgs.srv import *``: one of the two, whoever uses it telling
        which). Anything else stays unknown."""
        sources = self.program.library_star_sources(module)
        if not sources or len({s.rpartition(".")[0] for s in sources}) > 1:
            return TOP
        return join_all(self.extern(f"{source}.{name}") for source in sources)

    # -- modules ----------------------------------------------------------------------------
    def module_value(self, dotted: str) -> Value:
        if dotted in self.program.modules:
            return atoms([ModuleAtom(dotted)])
        return atoms([Extern(self.lib.canonical(dotted))])

    def import_member(self, base: str, name: str, attribute: bool = False) -> Value:
        """``from base import name``, or the attribute ``base.name`` (``attribute``)."""
        full = f"{base}.{name}" if base else name
        if full in self.program.modules:
            return atoms([ModuleAtom(full)])
        module = self.program.ensure(base)
        if module is not None:
            if name in module.globals or name in self.program.star_names(module):
                return self.load_global(module, name)
            if attribute and name in self.program.stored_attrs:
                # Set from outside (``DR_init.node = node`` in the script that then imports
                # the module reading it): what those stores wrote, nothing before that (the
                # read would raise AttributeError). Not for ``from base import name``: a
                # workspace folder named like a library lacks the library's names.
                return self.an.read(("g", module.name, name), self.frame.task)
            # A workspace folder named like a library (a ROS package's ``launch/``) that lacks the
            # name: Python would fail on it, so working code imports the library's.
            return self.extern(full) if self.lib.knows(full) else TOP
        return self.extern(full)

    def extern(self, qualname: str) -> Value:
        qualname = self.lib.canonical(qualname)
        constant = self.lib.constants.get(qualname)
        if constant is not None:
            return constant
        return atoms([Extern(qualname)])


def _listed_constants(value: Value) -> list | None:
    """The constants a container value lists, when every possibility is a tuple or list of
    known items, or a dict literal of known keys, that code cannot fill elsewhere; else
    ``None``."""
    if value.is_top or value.is_bottom:
        return None
    out: list = []
    for atom in value:
        if isinstance(atom, Seq) and not may_be_filled_elsewhere(atom):
            items = [item.consts() for item in atom.items]
        elif isinstance(atom, DictAtom) and not may_be_filled_elsewhere(atom):
            items = [key.consts() for key, _ in atom.items]
        else:
            return None
        if any(found is None or len(found) != 1 for found in items):
            return None
        out.extend(found[0] for found in items if found[0] not in out)
    return out if len(out) <= MAX_ATOMS else None


def _listed_items(value: Value, length: int) -> tuple[Value, ...] | None:
    """The items of ``value`` when it is one sequence of ``length`` listed items."""
    if value.is_top or len(value.atoms) != 1:
        return None
    [atom] = value.atoms
    return atom.items if isinstance(atom, Seq) and len(atom.items) == length else None


def _with_field(holder: Value, name: str, value: Value) -> Value:
    out = []
    for atom in holder:
        if isinstance(atom, Record):
            fields = dict(atom.fields)
            fields[name] = value
            atom = Record(atom.qualname, tuple(sorted(fields.items())))
        out.append(atom)
    return atoms(out, holder.soft)


def _as_load(target: ast.expr) -> ast.expr:
    if isinstance(target, ast.Name):
        return ast.Name(id=target.id, ctx=ast.Load())
    if isinstance(target, ast.Attribute):
        return ast.Attribute(value=target.value, attr=target.attr, ctx=ast.Load())
    return target


def _join_env(old: Env, new: Env, widen: bool) -> Env:
    out = dict(old)
    for name, value in new.items():
        prev = out.get(name)
        if prev is None:
            out[name] = value
        elif prev is not value:  # a value joined or widened with itself is itself
            out[name] = prev.widen(value) if widen else prev.join(value)
    join_remembered(out, old, new)
    return out
