"""Calls: user functions through the engine's tasks, library models, and pure builtins.

A user call binds arguments to a context tuple and reads the callee task's return
summary (the engine re-runs the caller when it grows).  A library call binds to the
stub's real parameter list, records the declared effects, performs stores, schedules
callbacks and builds the modelled return value.
"""
from __future__ import annotations

import ast
import itertools
import posixpath
import re
import string
from dataclasses import dataclass
from typing import Iterator

from .attrflow import is_remembered
from .callgraph import CallSite
from .containers import MAX_DICT_ITEMS, may_be_filled_elsewhere
from .engine import Effect
from .fieldclasses import Field
from .fixtures import is_test_class, test_class_calls
from .folding import (PURE_BUILTINS, PURE_LIBRARY, call_str_method, fold, fold_text, safe_template,
                      wide_template)
from .frame import Frame
from .library import FunctionModel, Ref, ReturnSpec, StandIn
from .passed_in import annotation, passed_in_site
from .program import Function
from .typetests import isinstance_value
from .values import (BOOLS, BOTTOM, MAX_ATOMS, TOP, Atom, BoundMethod, ClassAtom, Coll, Const, DictAtom,
                     Extern, ExternBound, FuncAtom, Input, Obj, Partial, Record, Seq, SuperAtom, Value,
                     atoms, const, from_input, join_all, soften)


#: ``object.__new__``: what a class's own ``__new__`` calls to make the instance.
OBJECT_NEW = "builtins.object.__new__"
#: What a ``@contextlib.contextmanager`` function's call returns: a record whose ``entered``
#: field is what the generator yields (the stdlib stub gives its ``__enter__``).
GENERATOR_CONTEXT_MANAGER = "contextlib._GeneratorContextManager"


class CallSemantics:
    """Call semantics, mixed into :class:`~.interpreter.Interpreter`."""

    def super_value(self, node: ast.Call) -> Value:
        frame = self.frame
        if node.args:
            classes = self.eval(node.args[0])
            receivers = self.eval(node.args[1]) if len(node.args) > 1 else TOP
            cids = [a.cid for a in classes if isinstance(a, ClassAtom)]
        else:
            func = frame.func
            cids = [func.cls] if func is not None and func.cls is not None else []
            params = self.param_names(func) if func is not None else []
            receivers = frame.env.get(params[0], TOP) if params else TOP
        if receivers.is_top or not cids:
            return TOP
        return atoms(SuperAtom(cid, recv) for cid in cids for recv in receivers)

    def call_method(self, target: Value, name: str, args: list[Value], node) -> Value:
        return self.call(self.load_attr(target, name), Args(args, {}, False), node)

    def call(self, func: Value, args: "Args", node: ast.AST | None) -> Value:
        self.forget_for_call(func)
        if func.is_top:
            self._escape(args)
            return TOP
        if len(func.atoms) == 1:  # the common case: nothing to order
            return self._call_atom(next(iter(func.atoms)), args, node)
        out = BOTTOM
        for atom in func:
            out = out.join(self._call_atom(atom, args, node))
        return out

    def _escape(self, args: "Args") -> None:
        """Callables passed to unknown code may be called by it: analyse them as entries.
        So may those inside a list, tuple or dict passed to it (a table of handlers, the
        namespace ``type(name, bases, ns)`` builds a class from)."""
        for value in list(args.pos) + list(args.kw.values()):
            self.escape_value(value)

    def escape_value(self, value: Value) -> None:
        """Analyse the callables in ``value`` (and in the containers it holds) as entries:
        unknown code receives it."""
        for atom in value:
            if isinstance(atom, (FuncAtom, BoundMethod, Partial)) or self._callable_object(atom):
                self.schedule_callback(atom)
            elif isinstance(atom, Seq):
                for item in atom.items:
                    self.escape_value(item)
            elif isinstance(atom, Coll):
                self.escape_value(atom.elem)
            elif isinstance(atom, DictAtom):
                for key, item in atom.items:
                    self.escape_value(key)
                    self.escape_value(item)

    def _call_atom(self, atom: Atom, args: "Args", node) -> Value:
        if isinstance(atom, FuncAtom):
            return self.call_user(atom.fid, None, args, node)
        if isinstance(atom, BoundMethod):
            return self.call_user(atom.fid, atom.receiver, args, node)
        if isinstance(atom, ClassAtom):
            return self.instantiate(atom, args, node)
        if isinstance(atom, Extern):
            return self.call_extern(atom.qualname, args, node)
        if isinstance(atom, ExternBound):
            return self.call_bound_extern(atom, args, node)
        if isinstance(atom, Partial):
            return self._call_atom(atom.func, _applied(atom, args), node)
        method = self._callable_object(atom)
        if method is not None:
            return self.call(method, args, node)
        return TOP

    def _callable_object(self, atom: Atom) -> Value | None:
        """``__call__`` bound to ``atom`` when it is an instance of a workspace class that
        defines one (a functor handed over as a callback, called like a function)."""
        if not isinstance(atom, Obj) or not isinstance(atom.cls, ClassAtom):
            return None
        return self.class_attr(self.mro(atom.cls), "__call__", atom)

    # -- user code ----------------------------------------------------------------------------
    def param_names(self, func: Function) -> list[str]:
        a = func.node.args
        names = [p.arg for p in a.posonlyargs + a.args]
        if a.vararg:
            names.append(a.vararg.arg)
        names.extend(p.arg for p in a.kwonlyargs)
        if a.kwarg:
            names.append(a.kwarg.arg)
        return names

    def bind_user(self, func: Function, receiver: Atom | None, args: "Args") -> tuple | None:
        """The context tuple for calling ``func``; ``None`` if an argument is still ⊥."""
        a = func.node.args
        positional = a.posonlyargs + a.args
        pos = ([atoms([receiver])] if receiver is not None else []) + list(args.pos)
        defaults = [None] * (len(positional) - len(a.defaults)) + list(a.defaults)
        ctx: list[Value] = []
        for i, (param, default) in enumerate(zip(positional, defaults)):
            if i < len(pos):
                ctx.append(pos[i])
            elif param.arg in args.kw:
                ctx.append(args.kw[param.arg])
            elif args.star:
                ctx.append(TOP)
            elif default is not None:
                ctx.append(self.eval_default(func, default))
            else:
                ctx.append(TOP)
        if a.vararg:
            extra = pos[len(positional):]
            ctx.append(atoms([Coll("tuple", TOP)]) if args.star else
                       atoms([Seq("tuple", tuple(extra))]))
        for param, default in zip(a.kwonlyargs, a.kw_defaults):
            if param.arg in args.kw:
                ctx.append(args.kw[param.arg])
            elif default is not None and not args.star:
                ctx.append(self.eval_default(func, default))
            else:
                ctx.append(TOP)
        if a.kwarg:
            known = {p.arg for p in positional + a.kwonlyargs}
            rest = tuple((const(k), v) for k, v in sorted(args.kw.items()) if k not in known)
            ctx.append(atoms([Coll("dict", TOP)]) if args.star else atoms([DictAtom(rest)]))
        if any(v.is_bottom for v in ctx):
            return None
        return tuple(ctx)

    def eval_default(self, func: Function, expr: ast.expr) -> Value:
        outer = self.frame
        task = outer.task if outer is not None else ("mod", func.module.name, ())
        self.frame = Frame(task, func.module)
        try:
            return self.eval(expr)
        finally:
            self.frame = outer

    def default_context(self, fid: int, receiver: Atom | None) -> tuple:
        func = self.program.functions[fid]
        ctx = self.bind_user(func, receiver, Args([], {}, False))
        if ctx is None:
            return tuple(TOP if v.is_bottom else v for v in self._bind_loose(func, receiver))
        # A parameter nothing gave (no default) may be an object the caller made out of sight.
        return tuple(self._passed_in(func, name) if value.is_top else value
                     for name, value in zip(self.param_names(func), ctx))

    def entry_contexts(self, fid: int) -> list[tuple]:
        """The contexts a function no analysed code calls is analysed in: its default context
        — one per combination of the values pytest's ``parametrize`` lists for a test's
        parameters, as pytest runs it once with each, so that a value stays with the names
        built from it (a robot's node and its topics); more combinations than the function's
        contexts keep their own leave them unknown."""
        ctx = self.default_context(fid, None)
        names = self.param_names(self.program.functions[fid])
        combinations = [ctx]
        for name, values in self.fixtures.listed_values(self.program.functions[fid]).items():
            if name in names:
                at = names.index(name)
                combinations = [c[:at] + (v,) + c[at + 1:] for c in combinations for v in values]
        return combinations if len(combinations) <= self.an.context_bound(fid) else [ctx]

    def _bind_loose(self, func: Function, receiver: Atom | None) -> list[Value]:
        names = self.param_names(func)
        first = [atoms([receiver])] if receiver is not None else []
        return first + [self._passed_in(func, name) for name in names[len(first):]]

    def _passed_in(self, func: Function, name: str) -> Value:
        """What an entry's parameter ``name`` holds: unknown, or the object of unknown identity
        its annotation's class stands for when the library says such objects are passed in
        (see :mod:`.passed_in`). A pytest fixture's parameter keeps the fixture's value."""
        written = annotation(func, name)
        if written is None or name in self.fixtures.arguments(func):
            return TOP
        outer, self.frame = self.frame, Frame(("mod", func.module.name, ()), func.module)
        try:
            cls = self._annotated_class(written, func.module)
        finally:
            self.frame = outer
        if not isinstance(cls, Extern) or not self.lib.class_flag(cls.qualname, "passed_in"):
            return TOP
        return atoms([Obj(passed_in_site(func.fid, name), cls)])

    def _annotated_class(self, expr: ast.expr, module) -> Atom | None:
        """The one class a dotted annotation names, read in ``module``'s globals."""
        value = self.load_global(module, expr.id) if isinstance(expr, ast.Name) else None
        if isinstance(expr, ast.Attribute):
            holder = self._annotated_class(expr.value, module)
            value = self.load_attr(atoms([holder]), expr.attr) if holder is not None else None
        if value is None or value.is_top or value.is_bottom or len(value.atoms) != 1:
            return None
        return next(iter(value.atoms))

    def call_user(self, fid: int, receiver: Atom | None, args: "Args", node=None) -> Value:
        func = self.program.functions[fid]
        ctx = self.bind_user(func, receiver, args)
        if ctx is None:
            return BOTTOM
        task = self.an.function_task(fid, ctx)
        self.record_call(node, ("task", task))
        self.an.run_now(task)
        if func.context_manager:
            entered = self.an.read(("yield", task), self.frame.task)
            return atoms([Record(GENERATOR_CONTEXT_MANAGER, (("entered", entered),))])
        return self.an.read(("ret", task), self.frame.task)

    def record_call(self, node, callee: tuple, args: tuple = (), effects: tuple = ()) -> None:
        """Note the call at ``node`` in the current task's call sites (see :mod:`.callgraph`)."""
        frame = self.frame
        if node is None or not hasattr(node, "lineno"):
            return
        conditional = self.conditional_here()
        frame.calls[(id(node), callee)] = CallSite(
            frame.module.path, node.lineno, frame.module.column(node), callee,
            conditional, frame.guarded, args, effects, node,
            self._caught() if effects and frame.catching else (),
            conditional and frame.func is None and frame.cls is None
            and any(first <= node.lineno <= last for first, last in frame.module.script_steps))

    def _caught(self) -> tuple[str, ...]:
        """What the ``except`` clauses around the current operation catch (see
        :attr:`.CallSite.caught`). Only names and tuples of names are evaluated: a clause
        that computes its class (``except pick_error():``) is ``?``."""
        out: list[str] = []
        for handler in self.frame.catching:
            if handler.type is None:
                out.append("builtins.BaseException")
                continue
            written = handler.type.elts if isinstance(handler.type, ast.Tuple) else [handler.type]
            for expr in written:
                value = self.eval(expr) if isinstance(expr, (ast.Name, ast.Attribute)) else TOP
                names = [a.qualname if isinstance(a, Extern) else self.program.classes[a.cid].qualname
                         for a in value if isinstance(a, (Extern, ClassAtom))] if not value.is_top else []
                out.extend(names if names and len(names) == len(value.atoms) else ["?"])
        return tuple(out)

    def conditional_here(self) -> bool:
        """Whether the current operation runs on some normal paths through the body only."""
        frame = self.frame
        return frame.cls is None and frame.block not in frame.dominators

    def schedule_callback(self, atom: Atom) -> None:
        """Analyse a callable that the library (or unknown code) calls later, as an entry:
        its parameters take their defaults, or unknown values where the caller passes them;
        a partial's bound arguments fill the parameters they bind."""
        bound = Args([], {}, False)
        while isinstance(atom, Partial):
            bound = _applied(atom, bound)
            atom = atom.func
        method = self._callable_object(atom)
        if method is not None:
            for called in method:
                self.schedule_callback(called if not bound.pos and not bound.kw else
                                       Partial(called, tuple(bound.pos), tuple(bound.kw.items()), bound.star))
            return
        if not isinstance(atom, (FuncAtom, BoundMethod)):
            return
        receiver = atom.receiver if isinstance(atom, BoundMethod) else None
        ctx = self.bind_user(self.program.functions[atom.fid], receiver, bound) \
            if bound.pos or bound.kw or bound.star else None
        if ctx is None:
            ctx = self.default_context(atom.fid, receiver)
        self.an.schedule(self.an.function_task(atom.fid, ctx))

    def instantiate(self, cls: ClassAtom, args: "Args", node) -> Value:
        new = self.class_attr(self.mro(cls), "__new__", None)
        if new is not None and any(isinstance(a, FuncAtom) for a in new):
            return self._instantiate_through_new(cls, new, args, node)
        return atoms([self.allocate(cls, node, args)])

    def allocate(self, cls: ClassAtom, node, args: "Args | None" = None) -> Obj:
        """A new instance of ``cls`` made at ``node``; built by its ``__init__`` when ``args``."""
        obj = Obj(self._site(node), cls)
        self.an.allocated.add(cls.cid)
        self.an.objects.setdefault(cls.cid, set()).add(obj)
        if args is not None:
            self.construct(obj, args, node)
        return obj

    def _instantiate_through_new(self, cls: ClassAtom, new: Value, args: "Args", node) -> Value:
        """``Cls(...)`` of a class that defines ``__new__`` (a singleton, a cache of
        instances): Python calls ``__new__(Cls, ...)`` and then ``__init__`` on what it
        returns when that is an instance of the class; anything else is the result as is."""
        result = self.call(new, Args([atoms([cls]), *args.pos], args.kw, args.star), node)
        for atom in result:
            if isinstance(atom, Obj) and isinstance(atom.cls, ClassAtom) and cls in self.mro(atom.cls):
                self.construct(atom, args, node)
        return result

    def construct(self, obj: Obj, args: "Args", node) -> None:
        fields = self.init_fields(obj.cls)
        if fields is not None:
            self._set_fields(obj, *fields, args)
            post = self.class_attr(self.mro(obj.cls), "__post_init__", obj) if fields[1] else None
            if post is not None:
                self.call(post, Args([], {}, False), node)
        else:
            init = self.class_attr(self.mro(obj.cls), "__init__", obj)
            if init is not None:
                self.call(init, args, node)
        for lib_cls in [c.qualname for c in self.mro(obj.cls) if isinstance(c, Extern)]:
            for name in self.lib.called_methods(lib_cls):
                method = self.class_attr(self.mro(obj.cls), name, obj)
                for atom in method or ():
                    if isinstance(atom, BoundMethod):
                        self.schedule_callback(atom)

    def _set_fields(self, obj: Obj, fields: list, positional: bool, args: "Args") -> None:
        """Write what a field-built ``__init__`` stores (see :mod:`.fieldclasses`): each field its
        argument, by position when ``positional``, else by keyword; a field not given keeps
        its default (a ``field(...)`` default is unknown); under ``*args``/``**kwargs`` every
        field not named may be given, so it is unknown. Keyword-only classes whose library
        ``__init__`` is not modelled only get the fields their keywords name."""
        given = [f for f in fields if f.init]
        pos = list(args.pos) if positional else []
        for i, found in enumerate(given):
            site = ("a", obj.site, found.name)
            if i < len(pos):
                self.an.write(site, pos[i])
            elif found.name in args.kw:
                self.an.write(site, args.kw[found.name])
            elif args.star:
                self.an.write(site, TOP)
            elif found.computed_default and positional:
                self.an.write(site, self._field_default(found))
            elif positional and found.has_default:
                default = self.class_attr(self.mro(obj.cls), found.name, obj)
                self.an.write(site, TOP if default is None else default)
            elif positional:
                self.an.write(site, TOP)  # a required field not passed: TypeError, or unseen

    def _field_default(self, found: Field) -> Value:
        """The default a ``field(...)`` gives: its ``default=`` literal, or what its
        ``default_factory=`` makes: a lambda's result (``lambda: ['front', 'rear']``) or an
        empty builtin container; anything else unknown."""
        expr = found.default_expr
        if expr is None:
            return TOP
        if not found.factory:
            try:
                return _literal(ast.literal_eval(expr))
            except (ValueError, TypeError, SyntaxError, MemoryError, RecursionError):
                return TOP
        if isinstance(expr, ast.Lambda):
            return self.call(atoms([FuncAtom(self.program.fid_of[id(expr)])]), Args([], {}, False), None)
        if isinstance(expr, ast.Name) and expr.id in ("list", "dict", "set", "tuple"):
            return self.call_builtin(expr.id, Args([], {}, False), None)
        return TOP

    def instantiate_entry(self, cid: int) -> None:
        """Analyse a class nothing instantiates, as if a library created it with unknown arguments."""
        klass = self.program.classes[cid]
        obj = Obj(f"entry:{klass.module.path}:{klass.qualname}", ClassAtom(cid))
        self.an.allocated.add(cid)
        self.an.objects.setdefault(cid, set()).add(obj)
        # Lookups need a frame; the class's module top level is the task that re-runs
        # (harmlessly) if what they read grows.
        outer, self.frame = self.frame, Frame(("mod", klass.module.name, ()), klass.module)
        try:
            self._schedule_entry(obj, cid)
        finally:
            self.frame = outer

    def call_uncalled(self, obj: Obj, names: list[str]) -> bool:
        """Schedule each of ``obj``'s methods ``names`` that has no task yet, bound to ``obj``,
        every other argument unknown; whether any was scheduled."""
        klass = self.program.classes[obj.cls.cid]
        outer, self.frame = self.frame, Frame(("mod", klass.module.name, ()), klass.module)
        added = False
        try:
            for name in names:
                for atom in self.class_attr(self.mro(obj.cls), name, obj) or ():
                    if isinstance(atom, BoundMethod) and atom.fid not in self.an.called:
                        func = self.program.functions[atom.fid]
                        if func.kind in ("function", "property"):
                            self.an.schedule(self.an.function_task(
                                atom.fid, tuple(self._bind_loose(func, atom.receiver))))
                            added = True
        finally:
            self.frame = outer
        return added

    def _schedule_entry(self, obj: Obj, cid: int) -> None:
        fields = self.init_fields(obj.cls)
        if fields is not None:  # built by unknown code: not with the fields' defaults
            self._set_fields(obj, fields[0], fields[1], Args([], {}, True))
        init = self.class_attr(self.mro(obj.cls), "__init__", obj)
        given = self._framework_arguments(obj, cid)
        for atom in init or ():
            if isinstance(atom, BoundMethod) and given:
                func = self.program.functions[atom.fid]
                ctx = self.bind_user(func, atom.receiver, Args(given, {}, False))
                self.an.schedule(self.an.function_task(
                    atom.fid, ctx if ctx is not None else self.default_context(atom.fid, atom.receiver)))
            elif isinstance(atom, BoundMethod):
                self.schedule_callback(atom)
        for lib_cls in self.library_bases(cid):
            for name in self.lib.called_methods(lib_cls):
                for atom in self.class_attr(self.mro(obj.cls), name, obj) or ():
                    if isinstance(atom, BoundMethod):
                        self.schedule_callback(atom)
        klass = self.program.classes[cid]
        if is_test_class(klass):
            names = {n for c in [cid, *self.user_bases(cid)] for n in self.program.classes[c].methods}
            for name in test_class_calls(klass, names):
                for atom in self.class_attr(self.mro(obj.cls), name, obj) or ():
                    self.schedule_callback(atom)

    def _framework_arguments(self, obj: Obj, cid: int) -> list[Value]:
        """What the framework passes when it instantiates ``obj`` (``entry_args`` of its first
        library base that declares some): a new object per argument, made by its modelled
        ``__init__`` with no arguments at the class definition (an rqt plugin's context).
        Their effects belong to a task of their own, ``("framework", module, (class,))``:
        no task of the workspace runs that code."""
        klass = self.program.classes[cid]
        for lib_cls in [*self.library_bases(cid), *self._registered_base(cid)]:
            model = self.lib.classes.get(lib_cls)
            if model is None or not model.entry_args:
                continue
            outer = self.frame
            # The framework always makes them: nothing here is conditional.
            self.frame = Frame(("framework", klass.module.name, (klass.qualname,)), klass.module,
                               dominators=frozenset({0}))
            out = []
            try:
                for index, qualname in enumerate(model.entry_args):
                    qualname = self.lib.canonical(qualname)
                    arg = Obj(f"{obj.site}#arg{index}", Extern(qualname))
                    init = self.lib.method(qualname, "__init__")
                    if init is not None:
                        self.apply_model(init, arg, Args([], {}, False), klass.node)
                    out.append(atoms([arg]))
                self.an.effects[self.frame.task] = self.frame.effects
            finally:
                self.frame = outer
            return out
        return []

    def _registered_base(self, cid: int) -> list[str]:
        """The modelled class the registration of class ``cid`` names as the base of what it
        registers (an rqt plugin whose Python base is qt_gui's ``Plugin``, registered as an
        ``rqt_gui_py::Plugin``, is built by rqt_gui_py with its ROS 2 context)."""
        klass = self.program.classes[cid]
        written = self.an.framework_classes.get(f"{klass.module.name}.{klass.qualname}")
        found = self.lib.registered_base(written) if written else None
        return [*self.lib.mro(found)] if found else []

    def _site(self, node) -> str:
        """The allocation site of an object created at ``node``: the source position, plus
        the calling context inside functions, so that a factory called twice yields two
        objects (one level of heap cloning, bounded by the contexts per function)."""
        line = getattr(node, "lineno", 0)
        col = getattr(node, "col_offset", 0)
        site = f"{self.frame.module.path}:{line}:{col}"
        task = self.frame.task
        if task[0] == "fn":
            site += f"@{self.an.context_index(task[1], task[2])}"
        return site

    # -- library code ---------------------------------------------------------------------------
    def call_extern(self, qualname: str, args: "Args", node) -> Value:
        if qualname == OBJECT_NEW:
            # ``super().__new__(cls)`` in a ``__new__``: a new, not yet initialised instance.
            classes = args.pos[0] if args.pos else TOP
            made = [self.allocate(a, node) for a in classes if isinstance(a, ClassAtom)]
            return atoms(made) if made and not classes.is_top else TOP
        if qualname.startswith("builtins."):
            return self.call_builtin(qualname[len("builtins."):], args, node)
        pure = PURE_LIBRARY.get(qualname)
        if pure is not None and args.pos and not args.kw and not args.star and all(
                v.strings() is not None for v in args.pos):
            return fold(pure, list(args.pos))
        owner, _, method = qualname.rpartition(".")
        fn = self.lib.functions.get(qualname) or (
            self.lib.method(owner, method) if owner in self.lib.classes else None)
        if fn is not None:  # a function, or a method called on the class (self passed explicitly)
            return self.apply_model(fn, None, args, node)
        if qualname in self.lib.classes:
            if self.lib.class_flag(qualname, "record"):
                # A record holds its constructor's arguments by name (``self`` excluded),
                # unless the constructor model says which fields it computes (``returns``):
                # then an attribute the class derives is not mistaken for a raw argument.
                init = self.lib.method(qualname, "__init__")
                if init is not None and init.returns.how == "record":
                    return self.apply_model(init, Const.of(None), args, node)
                bound = self.bind_model(init, Const.of(None), args) if init else {}
                bound.pop("self", None)
                return atoms([Record(qualname, tuple(sorted(bound.items())))])
            obj = Obj(self._site(node), Extern(qualname))
            init = self.lib.method(qualname, "__init__")
            if init is not None:
                self.apply_model(init, obj, args, node)
            return atoms([obj])
        self._escape(args)
        last = qualname.rsplit(".", 1)[-1]
        if last[:1].isupper():
            obj = Obj(self._site(node), Extern(qualname))
            self.record_construct(obj, args, node)
            return atoms([obj])
        return TOP

    def call_bound_extern(self, atom: ExternBound, args: "Args", node) -> Value:
        owner, _, name = atom.qualname.rpartition(".")
        if owner == "builtins.str":
            return self.call_str(atom.receiver, name, args)
        if owner == "builtins.container":
            return self.call_container(atom.receiver, name, args)
        model = self.lib.method(owner, name)
        if model is None:
            self._escape(args)
            return TOP
        receiver = atom.receiver
        if isinstance(receiver, Obj) and Extern(owner) not in self.mro(receiver.cls):
            return self._call_stand_in(model, owner, receiver, args, node)
        return self.apply_model(model, receiver, args, node)

    def _call_stand_in(self, model: FunctionModel, owner: str, receiver: Obj, args: "Args",
                       node) -> Value:
        """A method the receiver's unresolved base class may provide, modelled by a stand-in
        (:class:`~.library.StandIn`): the model's effects when the call has its shape, each
        marked with the base class (``unresolved_base``) so that consumers know the object is
        only presumed to be what the model describes; otherwise an unknown call."""
        name = model.qualname.rpartition(".")[2]
        declared = self.lib.classes.get(owner)
        spec = declared.stand_in_for_unresolved.get(name) if declared is not None else None
        base = self.unresolved_base(receiver.cls)
        if spec is None or base is None or not _has_shape(model, spec, args):
            self._escape(args)
            return TOP
        # An argument the call leaves out is whatever the unknown base class passes, not the
        # model's default: a base may well pass values of its own.
        return self.apply_model(model, receiver, args, node,
                                marks=(("unresolved_base", const(base)),), known_defaults=False)

    def bind_model(self, model: FunctionModel, receiver: Atom | None, args: "Args",
                   known_defaults: bool = True) -> dict:
        """Arguments of a library call by parameter name (⊥ arguments count as unknown; so do
        left-out ones without ``known_defaults``)."""
        params = model.signature.params
        pos = ([atoms([receiver])] if receiver is not None else []) + list(args.pos)
        bound: dict[str, Value] = {}
        positional = [p for p in params if p.kind == "pos"]
        for param, value in zip(positional, pos):
            bound[param.name] = value
        extra = pos[len(positional):]
        for param in params:
            if param.kind == "varargs":  # unknown when ``*seq`` may have added to it
                bound[param.name] = TOP if args.star else atoms([Seq("tuple", tuple(extra))])
            elif param.kind == "varkw":
                bound[param.name] = TOP if args.star else atoms([DictAtom(tuple(
                    (const(k), v) for k, v in sorted(args.kw.items())))])
            elif param.name in args.kw:
                bound[param.name] = args.kw[param.name]
            elif param.name not in bound:
                bound[param.name] = TOP if args.star or param.default is None or not known_defaults \
                    else param.default
        return {k: (TOP if v.atoms is not None and not v.atoms else v) for k, v in bound.items()}  # ⊥ -> ⊤

    @staticmethod
    def argument_texts(model: FunctionModel, receiver: Atom | None, node) -> dict[str, str]:
        """The source text of each argument written at the call ``node``, by parameter name."""
        if not isinstance(node, ast.Call):
            return {}
        positional = [p.name for p in model.signature.params if p.kind == "pos"][1 if receiver is not None else 0:]
        written: dict[str, ast.expr] = {}
        for name, arg in zip(positional, node.args):
            if isinstance(arg, ast.Starred):
                break
            written[name] = arg
        written.update((kw.arg, kw.value) for kw in node.keywords if kw.arg is not None)
        out = {}
        for name, expr in written.items():
            try:
                text = ast.unparse(expr)
            except (ValueError, RecursionError):  # a pathological expression: no text, not a failure
                continue
            out[name] = text if len(text) <= 80 else text[:77] + "..."
        return out

    def _argument_texts_at(self, model: FunctionModel, receiver: Atom | None, node) -> dict[str, str]:
        """:meth:`argument_texts`, kept per call site: a task re-runs its calls on every run,
        and unparsing the arguments again would give the same text (nodes outlive the analysis)."""
        key = (id(node), id(model), receiver is None)
        texts = self._texts.get(key)
        if texts is None:
            texts = self._texts[key] = self.argument_texts(model, receiver, node)
        return texts

    def apply_model(self, model: FunctionModel, receiver: Atom | None, args: "Args", node,
                    marks: tuple[tuple[str, Value], ...] = (), known_defaults: bool = True) -> Value:
        """Bind, compute the return value, record the effects (with ``marks`` appended to
        each one's arguments), perform the stores and schedule the callbacks of a library call
        (``known_defaults=False``: parameters the call leaves out are unknown)."""
        bound = self.bind_model(model, receiver, args, known_defaults)
        result = self.model_return(model.returns, bound, receiver, node)
        bound["@return"] = result
        frame = self.frame
        recorded = []
        written = self._argument_texts_at(model, receiver, node) if model.effects else {}
        for index, spec in enumerate(model.effects):
            values = tuple((name, self.ref(ref, bound, receiver)) for name, ref in spec.args) + marks
            texts = tuple((name, written[ref.data]) for name, ref in spec.args
                          if ref.how == "arg" and ref.data in written)
            key = (id(node), model.qualname, index, receiver, frame.row)
            frame.effects[key] = Effect(
                spec.kind, values, frame.module.path, getattr(node, "lineno", 0),
                frame.module.column(node) if node is not None else 0,
                self.conditional_here(), texts)
            recorded.append(frame.effects[key])
        self.record_call(node, ("lib", model.qualname), tuple(sorted(bound.items())),
                         tuple(recorded))
        for store in model.stores:
            for scope in _store_scopes(store, bound):
                value = self.ref(store.value, scope, receiver)
                for key in self.format_keys(store.key, scope):
                    for atom in scope.get(store.on, TOP):
                        if isinstance(atom, Obj):
                            self.an.write(("a", atom.site, key), value)
        passed = {name: (args_param, keywords_param)
                  for name, args_param, keywords_param in model.callback_args}
        for name in model.callbacks:
            value = bound.get(name, BOTTOM)
            if name in passed:
                value = _partial(value, _passed(bound, *passed[name]))
            for atom in value:
                self.schedule_callback(atom)
        return result

    def model_return(self, spec: ReturnSpec, bound: dict, receiver: Atom | None, node) -> Value:
        if spec.how == "enter":
            return self.call_method(bound.get(spec.data, TOP), "__enter__", [], node)
        if spec.how == "instance":
            qualname = self.lib.canonical(spec.data)
            return atoms([Obj(self._site(node), Extern(qualname))])
        if spec.how == "record":
            fields = tuple((k, self.ref(r, bound, receiver)) for k, r in spec.fields)
            return atoms([Record(spec.data, fields)])
        if spec.how == "ref":
            return self.ref(spec.data, bound, receiver)
        if spec.how == "partial":
            return _partial(bound.get(spec.data, TOP), {k: self.ref(r, bound, receiver) for k, r in spec.fields})
        return TOP

    def ref(self, ref: Ref, bound: dict, receiver: Atom | None) -> Value:
        value = self._ref_value(ref, bound, receiver)
        if ref.input is None:
            return value
        on, template = ref.input
        holders, keys = list(bound.get(on, TOP)), self.format_keys(template, bound)
        if len(holders) != 1 or not isinstance(holders[0], Obj) or len(keys) != 1:
            return value  # which object's setting, or which setting, is not known
        return from_input(value, Input(holders[0].site, keys[0]))

    def _ref_value(self, ref: Ref, bound: dict, receiver: Atom | None) -> Value:
        if ref.how == "arg":
            return bound.get(ref.data, TOP)
        if ref.how == "const":
            return ref.data
        if ref.how == "overridable":
            value = bound.get(ref.data, TOP)
            return TOP if ref.none_is_unset and value.consts() == [None] else soften(value)
        if ref.how == "format":
            keys = self.format_keys(ref.data, bound)
            return _soft_like(ref.data, bound, atoms(Const.of(k) for k in keys)) if keys else TOP
        if ref.how == "constant":
            return self.named_constant(ref.data, bound)
        if ref.how == "object":
            return self.named_object(*ref.data, bound)
        if ref.how == "field":
            if isinstance(receiver, Record):
                return receiver.field(ref.data) or TOP
            return TOP
        if ref.how == "load":
            out = BOTTOM
            keys = self.format_keys(ref.data, bound)
            holders = bound.get(ref.on, TOP)
            if not keys or holders.is_top:
                return TOP
            for atom in holders:
                if not isinstance(atom, Obj):
                    return TOP
                for key in keys:
                    value = self.an.read(("a", atom.site, key), self.frame.task)
                    out = out.join(TOP if value.is_bottom else value)
            return out if not out.is_bottom else TOP
        return TOP

    def named_constant(self, template: str, bound: dict) -> Value:
        """The library constants named by every expansion of ``template`` (unknown if one is
        not modelled).  Soft when an argument it is built from is: a lookup by an
        overridable name is itself only a default."""
        keys = self.format_keys(template, bound)
        out = BOTTOM
        for key in keys:
            found = self.lib.constants.get(self.lib.canonical(key))
            if found is None:
                return TOP
            out = out.join(found)
        return TOP if out.is_bottom else _soft_like(template, bound, out)

    def named_object(self, template: str, separator: str, shape: str, bound: dict) -> Value:
        """The library objects every expansion of ``template`` names, its dotted path written
        with ``separator`` between the parts (``'pkg/msg/Name'``: what ``from pkg.msg import
        Name`` binds). Unknown when one expansion does not have the ``shape`` (a regular
        expression matching the whole text) the library accepts: such a name means something
        else to it (a short name it completes), or nothing."""
        keys = self.format_keys(template, bound)
        if not keys or not all(re.fullmatch(shape, k) for k in keys):
            return TOP
        return _soft_like(template, bound, join_all(self.extern(k.replace(separator, ".")) for k in keys))

    def format_keys(self, template: str, bound: dict) -> list[str]:
        """All expansions of a key template over constant arguments.

        Fields are ``{param}`` or ``{param|filter}``, the filter one of :data:`KEY_FILTERS`.
        An empty list means the key is not statically known.
        """
        fields = sorted({f[1] for f in string.Formatter().parse(template) if f[1]})
        pools = []
        for name in fields:
            param, _, filt = name.partition("|")
            value = bound.get(param, TOP)
            values = KEY_FILTERS[filt](value) if filt in KEY_FILTERS else \
                (None if filt else value.consts())
            if not values:
                return []
            pools.append([str(v) for v in values])
        out = set()
        for combo in itertools.product(*pools):
            text = template
            for name, part in zip(fields, combo):
                text = text.replace("{" + name + "}", part)
            out.add(text)
            if len(out) > MAX_ATOMS:
                return []
        return sorted(out)

    # -- builtins ---------------------------------------------------------------------------
    def call_builtin(self, name: str, args: "Args", node) -> Value:
        pos = args.pos
        if name == "str" and len(pos) == 1 and not args.kw and not args.star \
                and pos[0].origin is not None and all(isinstance(c, str) for c in pos[0].consts() or ()):
            return pos[0]  # ``str()`` of a text setting is the setting, still named by its origin
        if name in PURE_BUILTINS and not args.kw and not args.star:
            if name == "str" and not pos:
                return const("")
            if pos and all(v.consts() is not None for v in pos):
                return fold(PURE_BUILTINS[name], list(pos))
            if name == "len" and len(pos) == 1:
                return _known_length(pos[0])
            return TOP
        if name == "range" and pos and all(v.consts() is not None for v in pos):
            out = fold(lambda *a: tuple(range(*a)) if len(range(*a)) <= MAX_ATOMS else _raise(),
                       list(pos), wrap=lambda r: Seq("list", tuple(const(x) for x in r)))
            return out if not out.is_top else atoms([Coll("list", TOP)])
        if name in ("list", "tuple", "sorted", "reversed", "set", "frozenset", "iter"):
            if not pos:
                return atoms([Seq("list", ())])
            if name in ("list", "tuple"):
                seqs = [a for a in pos[0]]
                if seqs and all(isinstance(a, Seq) for a in seqs):
                    return atoms(Seq(name, a.items) for a in seqs)
            return atoms([Coll(name, self.iter_elem(pos[0]))])
        if name == "enumerate" and pos:
            start = pos[1] if len(pos) > 1 else args.kw.get("start", const(0))
            items = _listed(pos[0])
            if items is not None and len(start.consts() or ()) == 1 and \
                    isinstance(start.consts()[0], int) and len(pos) <= 2:
                first = start.consts()[0]
                return atoms([Seq("list", tuple(atoms([Seq("tuple", (const(first + i), item))])
                                                for i, item in enumerate(items)))])
            return atoms([Coll("list", atoms([Seq("tuple", (TOP, self.iter_elem(pos[0])))]))])
        if name == "zip" and pos:
            columns = [_listed(p) for p in pos]
            if not args.kw and all(c is not None for c in columns):
                return atoms([Seq("list", tuple(atoms([Seq("tuple", row)]) for row in zip(*columns)))])
            return atoms([Coll("list", atoms([Seq("tuple", tuple(self.iter_elem(p) for p in pos))]))])
        if name == "dict":
            if args.kw and not pos:
                return atoms([DictAtom(tuple((const(k), v) for k, v in args.kw.items()))])
            return atoms([Coll("dict", TOP)])
        if name == "isinstance" and len(pos) == 2 and not args.kw and not args.star:
            return isinstance_value(pos[0], pos[1], self.lib.ancestors)
        if name in ("isinstance", "issubclass", "hasattr", "callable"):
            return BOOLS
        if name == "getattr" and len(pos) >= 2:
            names = pos[1].strings()
            if names:
                if len(pos) > 2 and all(self._never_set(pos[0], n) for n in names):
                    return pos[2]  # nothing can give the object that attribute: the default
                out = join_all(self.load_attr(pos[0], n) for n in names)
                return out.join(pos[2]) if len(pos) > 2 else out
            return TOP
        if name == "type" and len(pos) == 1 and not args.kw and not pos[0].is_top \
                and all(isinstance(a, Obj) for a in pos[0]):
            return atoms(a.cls for a in pos[0])
        if name == "setattr" and len(pos) == 3:
            names = pos[1].strings()
            for attr in names or ():
                self.store_attr(pos[0], attr, pos[2])
            if not names:  # any attribute it names may now hold the value
                self.store_any_attr(pos[0], pos[2])
                self.escape_value(pos[2])
            return const(None)
        if name in ("locals", "vars") and not pos and not args.kw and not args.star:
            return self.local_bindings()
        if name == "print":
            return const(None)
        if name in ("exec", "eval") and node is not None:
            self.not_followed(node, f"{name}() runs code the analysis does not follow: what it "
                                    "creates is not in the graph")
        self._escape(args)
        return TOP

    def local_bindings(self) -> Value:
        """``locals()`` in a function: its variables bound here, by name. Code that reads
        variables by name this way may call the functions among them wherever the dict goes
        (a test factory returns the tests it defines as ``{n: f for n, f in
        locals().items() if n.startswith("test_")}`` for a class built with ``type``), so
        those escape here, whatever the analysis makes of the dict later. Elsewhere (module
        or class body), or with more variables than a dict keeps, unknown."""
        frame = self.frame
        if frame.func is None or frame.cls is not None:
            return TOP
        bound = sorted((name, value) for name, value in frame.env.items()
                       if not name.startswith("$") and not is_remembered(name) and not value.is_bottom)
        for _, value in bound:
            self.escape_value(value)
        if len(bound) > MAX_DICT_ITEMS:
            return TOP
        return atoms([DictAtom(tuple((const(name), value) for name, value in bound))])

    def _never_set(self, value: Value, attr: str) -> bool:
        """Whether no object ``value`` may be can have ``attr``: workspace objects whose
        classes (and modelled library bases) define no such attribute and that no workspace
        code assigns it to (``getattr(self, "x", default)`` is then the default)."""
        if value.is_top or attr in self.program.stored_attrs:
            return False
        for atom in value:
            if not isinstance(atom, Obj) or not isinstance(atom.cls, ClassAtom):
                return False
            order = self.mro(atom.cls)
            if self.class_attr(order, attr, atom) is not None or any(
                    isinstance(c, Extern) and self.lib.method(c.qualname, attr) for c in order):
                return False
        return True

    def call_str(self, receiver: Const, name: str, args: "Args") -> Value:
        recv = atoms([receiver])
        if name == "format":
            if wide_template(receiver.value) or not safe_template(receiver.value):
                return TOP
            names = sorted(args.kw)
            pools = [recv] + list(args.pos) + [args.kw[k] for k in names]
            n = len(args.pos)
            return fold_text(lambda s, *v: s.format(*v[:n], **dict(zip(names, v[n:]))), pools)
        if name == "join" and args.pos:
            out = BOTTOM
            for atom in args.pos[0]:
                if not isinstance(atom, Seq):
                    return TOP
                out = out.join(fold_text(lambda s, *parts: s.join(parts), [recv, *atom.items]))
            return out if not args.pos[0].is_top else TOP
        if args.kw or args.star:
            return TOP
        return call_str_method(name, recv, list(args.pos))

    def call_container(self, receiver: Atom, name: str, args: "Args") -> Value:
        if isinstance(receiver, DictAtom):
            if name == "get":
                key = args.pos[0] if args.pos else TOP
                found = self._subscript(receiver, key)
                if _has_keys(receiver, key):
                    return found  # ``{'a': 'scan'}.get('a', 'default')`` is never the default
                return found.join(args.pos[1] if len(args.pos) > 1 else const(None))
            if name == "items":  # pairs stay paired
                return atoms([Seq("list", tuple(atoms([Seq("tuple", kv)]) for kv in receiver.items))])
            if name == "keys":
                return atoms([Seq("list", tuple(k for k, _ in receiver.items))])
            if name == "values":
                return atoms([Seq("list", tuple(v for _, v in receiver.items))])
        if name in ("copy",):
            return atoms([receiver])
        if name in ("append", "extend", "insert", "add", "update", "clear", "remove"):
            return const(None)
        return TOP


def _literal(value: object) -> Value:
    """A Python literal (what ``ast.literal_eval`` gives) as a value; unknown past the bounds."""
    if isinstance(value, (list, tuple)):
        if len(value) > MAX_ATOMS:
            return TOP
        return atoms([Seq("list" if isinstance(value, list) else "tuple", tuple(_literal(v) for v in value))])
    if isinstance(value, dict):
        if len(value) > MAX_DICT_ITEMS:
            return TOP
        return atoms([DictAtom(tuple((_literal(k), _literal(v)) for k, v in value.items()))])
    if value is None or isinstance(value, (str, int, float, bool, bytes, complex)):
        return const(value)
    return TOP


def _has_keys(mapping: DictAtom, key: Value) -> bool:
    """Whether every value ``key`` may be is a key the dict literal lists (all its keys
    known): the lookup then finds it. A dict only grows through the mutations the
    analysis follows (``pop`` and ``del`` are a documented limit)."""
    wanted = key.consts()
    if not wanted:
        return False
    listed = set()
    for k, _ in mapping.items:
        consts = k.consts()
        if consts is None or len(consts) != 1:
            return False
        listed.add(consts[0])
    return all(w in listed for w in wanted)


def _listed(value: Value) -> tuple[Value, ...] | None:
    """The items of ``value`` when it is one sequence whose items are listed (and not an
    empty list that unseen code may fill): what ``zip``/``enumerate`` pair row by row."""
    if value.is_top or value.is_bottom or len(value.atoms) != 1:
        return None
    [atom] = value.atoms
    if not isinstance(atom, Seq) or may_be_filled_elsewhere(atom):
        return None
    return atom.items


def _known_length(value: Value) -> Value:
    """``len(value)`` where every possibility has a known length: a sequence or dict whose
    items are listed (``for i in range(len(self.topics))`` over a list the caller wrote);
    not an empty list or dict, which unseen code may fill (as its truth decides nothing)."""
    if value.is_top or value.is_bottom or value.soft or value.origin is not None:
        return TOP  # a default's length, not the run's (a parameter's list may be longer)
    lengths = []
    for atom in value:
        if isinstance(atom, (Seq, DictAtom)) and not may_be_filled_elsewhere(atom):
            lengths.append(len(atom.items))
        else:
            return TOP
    return atoms(Const.of(n) for n in sorted(set(lengths)))


def _has_shape(model: FunctionModel, spec: StandIn, args: "Args") -> bool:
    """Whether a call (without its receiver) binds to ``model``'s parameters exactly as Python
    would (no unpacking, no missing or surplus argument, no keyword the method lacks) and
    gives the parameters ``spec`` names arguments of their kinds."""
    if args.star:
        return False
    params = model.signature.params[1:]  # the receiver is ``self``
    positional = [p for p in params if p.kind == "pos"]
    named = {p.name for p in params if p.kind in ("pos", "kwonly")}
    if len(args.pos) > len(positional) and not any(p.kind == "varargs" for p in params):
        return False
    given = {p.name: v for p, v in zip(positional, args.pos)}
    for key, value in args.kw.items():
        if key in given or (key not in named and not any(p.kind == "varkw" for p in params)):
            return False
        given[key] = value
    if any(p.default is None and p.kind in ("pos", "kwonly") and p.name not in given
           for p in params):
        return False
    return all(_of_kind(given.get(param), kind) for param, kind in spec.kinds)


def _of_kind(value: Value | None, kind: str) -> bool:
    """Whether an argument has the kind a stand-in requires (``None``: not given)."""
    optional = kind.endswith("?")
    kind = kind.rstrip("?")
    if value is None or value.is_top or value.is_bottom:
        return optional
    for atom in value:
        if kind == "class":
            ok = isinstance(atom, ClassAtom) or (
                isinstance(atom, Extern) and atom.qualname.rpartition(".")[2][:1].isupper())
        elif kind == "function":
            ok = isinstance(atom, (FuncAtom, BoundMethod))
        elif kind == "str":
            ok = isinstance(atom, Const) and isinstance(atom.value, str)
        else:
            ok = isinstance(atom, Const) and isinstance(atom.value, (int, float)) \
                and not isinstance(atom.value, bool)
        if not ok:
            return False
    return True


def _argparse_dest(value: Value) -> list[str] | None:
    """argparse's ``dest`` for ``add_argument(*name_or_flags)``: first long option, else first name."""
    out = []
    for atom in value:
        if not isinstance(atom, Seq) or not atom.items:
            return None
        flags = [v.strings() for v in atom.items]
        if any(f is None or len(f) != 1 for f in flags):
            return None
        names = [f[0] for f in flags]
        chosen = next((n for n in names if n.startswith("--")), names[0])
        out.append(chosen.lstrip("-").replace("-", "_"))
    return out or None


def _soft_like(template: str, bound: dict, value: Value) -> Value:
    """``value``, soft when an argument the template is built from is: a name built from an
    overridable default is itself only a default."""
    used = {f[1].partition("|")[0] for f in string.Formatter().parse(template) if f[1]}
    return soften(value) if any(bound.get(p, TOP).soft for p in used) else value


def _upper(value: Value) -> list[str] | None:
    """``str.upper`` of every possible string."""
    strings = value.strings()
    return [s.upper() for s in strings] if strings else None


def _rooted(value: Value) -> list[str] | None:
    """Every possible string as an absolute POSIX path, ``None`` or ``""`` being the root:
    ``posixpath.join("/", value or "")``."""
    consts = value.consts()
    if not consts or not all(c is None or isinstance(c, str) for c in consts):
        return None
    return sorted({posixpath.join("/", c or "") for c in consts})


def _namespace_front(value: Value) -> list[str] | None:
    """Every possible value as the front of an absolute path a ``/`` and a name follow:
    ``None``, ``""`` and ``"/"`` give ``""`` (``/name``), ``"ns"`` gives ``"/ns"``."""
    rooted = _rooted(value)
    return sorted({r.rstrip("/") for r in rooted}) if rooted is not None else None


def _dotted(value: Value) -> list[str] | None:
    """Every possible prefix as the front of a dotted name: ``''`` and ``None`` stay empty,
    ``'ns'`` becomes ``'ns.'``."""
    consts = value.consts()
    if not consts or not all(c is None or isinstance(c, str) for c in consts):
        return None
    return sorted({f"{c}." if c else "" for c in consts})


#: Filters usable in library-model key templates (``{param|filter}``).
KEY_FILTERS = {"argparse_dest": _argparse_dest, "upper": _upper, "rooted": _rooted, "dotted": _dotted,
               "namespace_front": _namespace_front}


def _store_scopes(store, bound: dict) -> Iterator[dict]:
    """The bindings one store is made with: ``bound`` itself, or with ``each``, ``bound``
    plus ``@key``/``@value`` for every ``(key, value, …)`` entry of a list of known length
    (entries of a list of unknown length are not stored: nothing is invented)."""
    if store.each is None:
        yield bound
        return
    for table in bound.get(store.each, TOP):
        if not isinstance(table, Seq):
            continue
        for item in table.items:
            for entry in item:
                if isinstance(entry, Seq) and entry.items:
                    value = entry.items[1] if len(entry.items) > 1 else TOP
                    yield {**bound, "@key": entry.items[0], "@value": value}


@dataclass(frozen=True)
class Args:
    """Evaluated call arguments; ``star`` means some positions/keywords are unknown."""

    pos: list
    kw: dict
    star: bool


def _partial(func: Value, given: dict[str, Value]) -> Value:
    """Each callable of ``func`` with the positional arguments of the sequence ``args`` and
    the keywords of the mapping ``keywords`` bound in front. Arguments that are not a known
    sequence, or a mapping with string keys, leave every later position unknown: a value
    is never shifted onto the wrong parameter."""
    if func.is_top:
        return TOP
    args = given.get("args", atoms([Seq("tuple", ())]))
    keywords = given.get("keywords", atoms([DictAtom(())]))
    bindings = []
    for seq in [None] if args.is_top else args:
        for mapping in [None] if keywords.is_top else keywords:
            kw = _string_keys(mapping) if isinstance(mapping, DictAtom) else None
            known = isinstance(seq, Seq) and kw is not None
            bindings.append((seq.items if isinstance(seq, Seq) else (), kw or (), not known))
    return atoms(Partial(target, pos, kw, star) for target in func for pos, kw, star in bindings)


def _passed(bound: dict, args_param: str | None, keywords_param: str | None) -> dict[str, Value]:
    """The sequence and mapping a library calls a callback with (``Thread(target, args=(node,))``),
    as :func:`_partial` takes them; ``None`` (``kwargs=None``, the default) passes nothing."""
    out = {}
    for key, param in (("args", args_param), ("keywords", keywords_param)):
        value = bound.get(param, TOP) if param is not None else None
        if value is not None and value.consts() != [None]:
            out[key] = value
    return out


def _string_keys(mapping: DictAtom) -> tuple[tuple[str, Value], ...] | None:
    """A dict's items keyed by their single string keys; ``None`` if a key is not one string."""
    out = []
    for key, value in mapping.items:
        names = key.strings()
        if names is None or len(names) != 1:
            return None
        out.append((names[0], value))
    return tuple(sorted(out, key=lambda kv: kv[0]))


def _applied(partial: Partial, args: Args) -> Args:
    """The arguments a call of ``partial`` with ``args`` passes to what it wraps: the bound
    positionals first, the caller's keywords over the bound ones (as ``functools.partial``)."""
    pos = list(partial.args) + ([] if partial.star else list(args.pos))
    return Args(pos, {**dict(partial.kw), **args.kw}, partial.star or args.star)


def _raise():
    raise ValueError
