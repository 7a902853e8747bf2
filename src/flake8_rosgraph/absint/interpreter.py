"""Transfer functions: what each Python statement and expression does to abstract values.

:class:`Interpreter` runs one task's CFG to a local fixpoint (environments per block,
joined at merges, widened at loop heads) and evaluates expressions over the value
lattice.  Calls go to user functions (through the engine's task table, so every
context is analysed once and re-analysed when what it read grows), to library models
(effects, stores, callbacks, modelled returns), or to a few pure builtins that fold
on constants.  Anything it cannot follow becomes ⊤ — never an exception.
"""
from __future__ import annotations

import ast
import builtins
import heapq
import itertools
import string
from dataclasses import dataclass, field

from .cfg import CFG, Bind, Eval, Return
from .engine import MAX_BLOCK_VISITS, WIDEN_AFTER, Analysis, Effect, Task
from .folding import BINOPS, CMPOPS, PURE_BUILTINS, UNARYOPS, call_str_method, fold
from .library import FunctionModel, Ref, ReturnSpec
from .program import Class, Function, Module
from .values import (BOTTOM, MAX_ATOMS, TOP, Atom, BoundMethod, ClassAtom, Coll, Const, DictAtom,
                     Extern, ExternBound, FuncAtom, ModuleAtom, Obj, Record, Seq, SuperAtom, Value,
                     atoms, const, join_all, soften)

BUILTIN_NAMES = frozenset(dir(builtins))
Env = dict  # variable name -> Value
_BOOLS = atoms([Const.of(True), Const.of(False)])


@dataclass
class Frame:
    """Where evaluation currently happens: task, module, function or class body, block."""

    task: Task
    module: Module
    func: Function | None = None
    cls: Class | None = None
    dominators: frozenset[int] = frozenset()
    block: int = 0
    env: Env = field(default_factory=dict)
    effects: dict = field(default_factory=dict)
    comp: list[dict[str, Value]] = field(default_factory=list)
    ret: Value = BOTTOM


class Interpreter:
    def __init__(self, analysis: Analysis) -> None:
        self.an = analysis
        self.program = analysis.program
        self.lib = analysis.library
        self.frame: Frame | None = None

    # =====================================================================================
    # tasks and CFGs
    # =====================================================================================
    def run_task(self, task: Task) -> tuple[Value, dict]:
        if task[0] == "mod":
            module = self.program.modules[task[1]]
            frame = Frame(task, module)
            env: Env = {}
        else:
            func = self.program.functions[task[1]]
            frame = Frame(task, func.module, func)
            env = dict(zip(self.param_names(func), task[2]))
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
        return ret, frame.effects

    @staticmethod
    def _cfg_of(frame: Frame) -> CFG:
        if frame.func is not None:
            return frame.func.cfg
        if frame.module.cfg is None:
            from .cfg import build_cfg
            frame.module.cfg = build_cfg(frame.module.tree.body)
        return frame.module.cfg

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
            frame.env = dict(states[bid])
            for op in block.ops:
                self.exec_op(op)
            out = frame.env
            targets: list[tuple[int, Env]] = []
            for edge in block.succs:
                if edge.test is not None:
                    decided = self.truth(self.eval(edge.test), by_default=False)
                    if decided is not None and decided != edge.polarity:
                        continue
                targets.append((edge.target, out))
            for handler in block.exc_succs:
                targets.append((handler, states[bid]))
                targets.append((handler, out))
            for target, state in targets:
                old = states.get(target)
                if old is None:
                    new = dict(state)
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

    @staticmethod
    def _scope_name(frame: Frame) -> str:
        return frame.func.qualname if frame.func else f"module {frame.module.name}"

    # =====================================================================================
    # statements
    # =====================================================================================
    def exec_op(self, op) -> None:
        if isinstance(op, Eval):
            self.eval(op.expr)
        elif isinstance(op, Bind):
            self.exec_bind(op)
        elif isinstance(op, Return):
            value = const(None) if op.value is None else self.eval(op.value)
            self.frame.ret = self.frame.ret.join(value)
        else:
            method = getattr(self, "s_" + type(op).__name__, None)
            if method is not None:
                method(op)

    def exec_bind(self, op: Bind) -> None:
        if op.how == "iter":
            self.assign(op.target, self.iter_elem(self.eval(op.value)))
        elif op.how == "enter":
            ctx = self.eval(op.value)
            self.assign(op.target, self.call_method(ctx, "__enter__", [], op.value))
        elif op.how == "except":
            if op.value is not None:
                self.eval(op.value)
            self.assign(op.target, TOP)
        else:  # match captures
            subject = self.eval(op.value)
            for node in ast.walk(op.target):
                name = getattr(node, "name", None) or getattr(node, "rest", None)
                if isinstance(name, str):
                    whole = isinstance(node, ast.MatchAs) and node.pattern is None \
                        and node is op.target
                    self.store_name(name, subject if whole else TOP)

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

    def s_Import(self, op: ast.Import) -> None:
        for alias in op.names:
            if alias.asname:
                self.store_name(alias.asname, self.module_value(alias.name))
            else:
                top = alias.name.split(".")[0]
                self.store_name(top, self.module_value(top))

    def s_ImportFrom(self, op: ast.ImportFrom) -> None:
        base = self.program.resolve_import(self.frame.module, op.module, op.level)
        for alias in op.names:
            if alias.name == "*":
                self._star_import(base)
                continue
            self.store_name(alias.asname or alias.name, self.import_member(base, alias.name))

    def _star_import(self, base: str) -> None:
        module = self.program.modules.get(base)
        if module is None:
            return  # names from a library star import stay unknown (⊤ on lookup)
        for name in sorted(module.globals):
            if not name.startswith("_"):
                self.store_name(name, self.import_member(base, name))

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
            self.eval(kw.value)
        self.an.write(("bases", cid), atoms([Seq("tuple", bases)]))
        outer = self.frame
        inner = Frame(outer.task, outer.module, outer.func, klass, effects=outer.effects)
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
            if isinstance(target.value, ast.Name) and any(isinstance(a, Record) for a in holder):
                # Records (library value objects such as a QoS profile) are updated in place
                # through the variable that holds them.
                self.store_name(target.value.id, _with_field(holder, target.attr, value))
        elif isinstance(target, ast.Subscript):
            self.eval(target.value)
            self.eval(target.slice)
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
            if name in func.cellvars:
                self.an.write(("c", func.fid, name), value)

    def load_name(self, name: str) -> Value:
        frame = self.frame
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
            if name in func.locals and frame.cls is None:
                return frame.env.get(name, BOTTOM)
            if name not in func.global_decl:
                owner = func.fid if name in func.locals else \
                    self.program.closure_owner(func.fid, name)
                if owner is not None:
                    return self.an.read(("c", owner, name), frame.task)
        return self.load_global(frame.module, name)

    def load_global(self, module: Module, name: str) -> Value:
        if name in module.globals:
            return self.an.read(("g", module.name, name), self.frame.task)
        if name == "__name__":
            return TOP
        if name in BUILTIN_NAMES:
            return atoms([Extern("builtins." + name)])
        return TOP

    # -- modules ----------------------------------------------------------------------------
    def module_value(self, dotted: str) -> Value:
        if dotted in self.program.modules:
            return atoms([ModuleAtom(dotted)])
        return atoms([Extern(self.lib.canonical(dotted))])

    def import_member(self, base: str, name: str) -> Value:
        full = f"{base}.{name}" if base else name
        if full in self.program.modules:
            return atoms([ModuleAtom(full)])
        module = self.program.modules.get(base)
        if module is not None:
            return self.load_global(module, name) if name in module.globals else TOP
        return self.extern(full)

    def extern(self, qualname: str) -> Value:
        qualname = self.lib.canonical(qualname)
        constant = self.lib.constants.get(qualname)
        if constant is not None:
            return constant
        return atoms([Extern(qualname)])

    # =====================================================================================
    # expressions
    # =====================================================================================
    def eval(self, node: ast.expr) -> Value:
        method = getattr(self, "e_" + type(node).__name__, None)
        if method is None:
            return TOP
        return method(node)

    def e_Constant(self, node: ast.Constant) -> Value:
        return const(node.value)

    def e_Name(self, node: ast.Name) -> Value:
        return self.load_name(node.id)

    def e_Attribute(self, node: ast.Attribute) -> Value:
        return self.load_attr(self.eval(node.value), node.attr)

    def e_NamedExpr(self, node: ast.NamedExpr) -> Value:
        value = self.eval(node.value)
        self.assign(node.target, value)
        return value

    def e_JoinedStr(self, node: ast.JoinedStr) -> Value:
        parts = []
        for part in node.values:
            if isinstance(part, ast.Constant):
                parts.append(const(str(part.value)))
            elif isinstance(part, ast.FormattedValue):
                value = self.eval(part.value)
                if part.conversion in (ord("r"), ord("a")):
                    value = fold(repr, [value])
                spec = self.eval(part.format_spec) if part.format_spec else const("")
                parts.append(fold(format, [value, spec]))
            else:
                parts.append(TOP)
        return fold(lambda *p: "".join(p), parts)

    def e_BinOp(self, node: ast.BinOp) -> Value:
        return self.binop(node.op, self.eval(node.left), self.eval(node.right))

    def binop(self, op: ast.operator, left: Value, right: Value) -> Value:
        if left.is_bottom or right.is_bottom:
            return BOTTOM
        fn = BINOPS.get(type(op))
        if fn is None:
            return TOP
        if isinstance(op, ast.Mod) and right.consts() is None:
            tuples = _const_tuples(right)
            if tuples is None:
                return TOP
            return fold(fn, [left, atoms(Const("tuple", t) for t in tuples)])
        if isinstance(op, ast.Add) and left.consts() is None:
            items = [a for a in left] + [a for a in right]
            if items and all(isinstance(a, Seq) for a in items) and len(items) == 2:
                a, b = items
                return atoms([Seq(a.kind, a.items + b.items)])
        return fold(fn, [left, right])

    def e_UnaryOp(self, node: ast.UnaryOp) -> Value:
        value = self.eval(node.operand)
        if isinstance(node.op, ast.Not):
            decided = self.truth(value)
            return _BOOLS if decided is None else const(not decided)
        return fold(UNARYOPS[type(node.op)], [value])

    def e_BoolOp(self, node: ast.BoolOp) -> Value:
        out = BOTTOM
        for value_node in node.values:
            value = self.eval(value_node)
            decided = self.truth(value)
            stop = decided is (isinstance(node.op, ast.Or))
            if decided is None or stop or value_node is node.values[-1]:
                out = out.join(value)
            if stop:
                break
        return out

    def e_Compare(self, node: ast.Compare) -> Value:
        left = self.eval(node.left)
        result: Value | None = None
        for op, comp in zip(node.ops, node.comparators):
            right = self.eval(comp)
            step = self.compare(op, left, right)
            result = step if result is None else fold(lambda a, b: a and b, [result, step])
            left = right
        return result if result is not None else _BOOLS

    def compare(self, op: ast.cmpop, left: Value, right: Value) -> Value:
        fn = CMPOPS[type(op)]
        if left.consts() is not None and right.consts() is not None:
            return fold(fn, [left, right])
        if isinstance(op, (ast.Is, ast.IsNot, ast.Eq, ast.NotEq)) and not left.is_top \
                and not right.is_top:
            negate = isinstance(op, (ast.IsNot, ast.NotEq))
            out = set()
            for a in left:
                for b in right:
                    if isinstance(a, Const) and isinstance(b, Const):
                        out.add(fn(a.value, b.value))
                    elif isinstance(a, Const) != isinstance(b, Const) and \
                            None in (getattr(a, "value", 0), getattr(b, "value", 0)):
                        out.add(negate)  # an object is never None
                    else:
                        out.update((True, False))
            return atoms(Const.of(x) for x in out)
        return _BOOLS

    def e_IfExp(self, node: ast.IfExp) -> Value:
        decided = self.truth(self.eval(node.test))
        if decided is True:
            return self.eval(node.body)
        if decided is False:
            return self.eval(node.orelse)
        return self.eval(node.body).join(self.eval(node.orelse))

    def e_Tuple(self, node: ast.Tuple | ast.List) -> Value:
        kind = "tuple" if isinstance(node, ast.Tuple) else "list"
        items = []
        for elt in node.elts:
            if isinstance(elt, ast.Starred):
                inner = self.eval(elt.value)
                seqs = [a for a in inner if isinstance(a, Seq)]
                if len(seqs) == 1 and len(list(inner)) == 1:
                    items.extend(seqs[0].items)
                    continue
                return atoms([Coll(kind, TOP)])
            items.append(self.eval(elt))
        return atoms([Seq(kind, tuple(items))])

    e_List = e_Tuple

    def e_Set(self, node: ast.Set) -> Value:
        return atoms([Coll("set", join_all(self.eval(e) for e in node.elts))])

    def e_Dict(self, node: ast.Dict) -> Value:
        items = []
        for key, value in zip(node.keys, node.values):
            if key is None:
                self.eval(value)
                return atoms([Coll("dict", TOP)])
            items.append((self.eval(key), self.eval(value)))
        return atoms([DictAtom(tuple(items))])

    def e_Subscript(self, node: ast.Subscript) -> Value:
        container = self.eval(node.value)
        index = self.eval(node.slice)
        if container.is_top:
            return TOP
        out = BOTTOM
        for atom in container:
            out = out.join(self._subscript(atom, index))
        return out

    def _subscript(self, atom: Atom, index: Value) -> Value:
        keys = index.consts()
        if isinstance(atom, Seq) and keys is not None:
            out = BOTTOM
            for k in keys:
                if isinstance(k, int) and not isinstance(k, bool) and -len(atom.items) <= k < len(atom.items):
                    out = out.join(atom.items[k])
                else:
                    return TOP
            return out
        if isinstance(atom, Seq):
            return join_all(atom.items) if not index.is_top and all(
                isinstance(a, Const) for a in index) else TOP
        if isinstance(atom, Coll):
            return atom.elem
        if isinstance(atom, DictAtom):
            if keys is None:
                return join_all(v for _, v in atom.items)
            out = BOTTOM
            for k, v in atom.items:
                kc = k.consts()
                if kc is None or any(x in kc for x in keys):
                    out = out.join(v)
            return out
        if isinstance(atom, Const) and isinstance(atom.value, (str, bytes, tuple)):
            return fold(lambda s, i: s[i], [atoms([atom]), index])
        return TOP

    def e_Slice(self, node: ast.Slice) -> Value:
        return TOP

    def e_Starred(self, node: ast.Starred) -> Value:
        return self.eval(node.value)

    def e_Lambda(self, node: ast.Lambda) -> Value:
        for default in node.args.defaults:
            self.eval(default)
        return atoms([FuncAtom(self.program.fid_of[id(node)])])

    def e_Await(self, node: ast.Await) -> Value:
        return self.eval(node.value)

    def e_Yield(self, node: ast.Yield) -> Value:
        if node.value is not None:
            self.eval(node.value)
        return TOP

    e_YieldFrom = e_Yield

    def e_ListComp(self, node) -> Value:
        overlay: dict[str, Value] = {}
        self.frame.comp.append(overlay)
        try:
            for gen in node.generators:
                elem = self.iter_elem(self.eval(gen.iter))
                for name_node in ast.walk(gen.target):
                    if isinstance(name_node, ast.Name):
                        overlay[name_node.id] = TOP
                self.assign(gen.target, elem)
                for cond in gen.ifs:
                    self.eval(cond)
            if isinstance(node, ast.DictComp):
                self.eval(node.key)
                elem = self.eval(node.value)
            else:
                elem = self.eval(node.elt)
        finally:
            self.frame.comp.pop()
        kind = {ast.ListComp: "list", ast.SetComp: "set", ast.DictComp: "dict"}.get(
            type(node), "gen")
        return atoms([Coll(kind, elem)])

    e_SetComp = e_DictComp = e_GeneratorExp = e_ListComp

    def e_Call(self, node: ast.Call) -> Value:
        if isinstance(node.func, ast.Name) and node.func.id == "super" \
                and self.load_name("super") == atoms([Extern("builtins.super")]):
            return self.super_value(node)
        func = self.eval(node.func)
        args: list[Value] = []
        star = False
        for arg in node.args:
            if isinstance(arg, ast.Starred):
                inner = self.eval(arg.value)
                seqs = [a for a in inner if isinstance(a, Seq)]
                if len(seqs) == 1 and len(list(inner)) == 1:
                    args.extend(seqs[0].items)
                else:
                    star = True
            else:
                args.append(self.eval(arg))
        kwargs: dict[str, Value] = {}
        for kw in node.keywords:
            value = self.eval(kw.value)
            if kw.arg is not None:
                kwargs[kw.arg] = value
            else:
                dicts = [a for a in value if isinstance(a, DictAtom)]
                if len(dicts) == 1 and len(list(value)) == 1 and all(
                        k.strings() and len(k.strings()) == 1 for k, _ in dicts[0].items):
                    for k, v in dicts[0].items:
                        kwargs[k.strings()[0]] = v
                else:
                    star = True
        return self.call(func, Args(args, kwargs, star), node)

    # =====================================================================================
    # attributes
    # =====================================================================================
    def load_attr(self, value: Value, attr: str) -> Value:
        if value.is_top:
            return TOP
        out = BOTTOM
        for atom in value:
            out = out.join(self._attr_of(atom, attr))
            if out.is_top:
                return out
        return out

    def _attr_of(self, atom: Atom, attr: str) -> Value:
        task = self.frame.task
        if isinstance(atom, Obj):
            field_value = self.an.read(("a", atom.site, attr), task)
            found = self.class_attr(self.mro(atom.cls), attr, atom)
            if found is None:
                if field_value.is_bottom and attr not in self.program.stored_attrs \
                        and not self._all_user(atom.cls):
                    return TOP  # nothing here assigns it: the library's attribute
                return field_value
            return field_value.join(found)
        if isinstance(atom, ClassAtom):
            found = self.class_attr(self.mro(atom), attr, None)
            return TOP if found is None else found
        if isinstance(atom, SuperAtom):
            cls_of = atom.receiver.cls if isinstance(atom.receiver, Obj) else atom.receiver
            order = self.mro(cls_of)
            here = ClassAtom(atom.cid)
            if here in order:
                order = order[order.index(here) + 1:]
            found = self.class_attr(order, attr, atom.receiver)
            return TOP if found is None else found
        if isinstance(atom, ModuleAtom):
            return self.import_member(atom.name, attr)
        if isinstance(atom, Extern):
            model = self.lib.classes.get(atom.qualname)
            if model is not None and self.lib.method(atom.qualname, attr):
                return atoms([Extern(f"{atom.qualname}.{attr}")])
            return self.extern(f"{atom.qualname}.{attr}")
        if isinstance(atom, Record):
            field_value = atom.field(attr)
            if field_value is not None:
                return field_value
            if self.lib.method(atom.qualname, attr):
                return atoms([ExternBound(atom, f"{atom.qualname}.{attr}")])
            return TOP
        if isinstance(atom, Const) and isinstance(atom.value, str):
            return atoms([ExternBound(atom, "builtins.str." + attr)])
        if atom == Const.of(None):
            return BOTTOM  # AttributeError at run time: no value flows on
        if isinstance(atom, (Seq, Coll, DictAtom)):
            return atoms([ExternBound(atom, "builtins.container." + attr)])
        return TOP

    def _all_user(self, cls: Atom) -> bool:
        return all(isinstance(c, ClassAtom) or c == Extern("builtins.object")
                   for c in self.mro(cls))

    def class_attr(self, order: list[Atom], attr: str, receiver: Atom | None) -> Value | None:
        """Look ``attr`` up along a method resolution order; bind functions to ``receiver``."""
        for cls in order:
            if isinstance(cls, ClassAtom):
                value = self.an.read(("k", cls.cid, attr), self.frame.task)
                if value.is_bottom:
                    continue
                return self._bind(value, receiver, cls)
            model_method = self.lib.classes.get(cls.qualname)
            if model_method is not None and attr in model_method.methods:
                qual = f"{cls.qualname}.{attr}"
                return atoms([ExternBound(receiver, qual) if receiver is not None else Extern(qual)])
            constant = self.lib.constants.get(f"{cls.qualname}.{attr}")
            if constant is not None:
                return constant
        return None

    def _bind(self, value: Value, receiver: Atom | None, owner: ClassAtom) -> Value:
        if value.is_top:
            return value
        out = []
        for atom in value:
            if isinstance(atom, FuncAtom):
                kind = self.program.functions[atom.fid].kind
                if kind == "staticmethod":
                    out.append(atom)
                elif kind == "classmethod":
                    recv = receiver.cls if isinstance(receiver, Obj) else owner
                    out.append(BoundMethod(recv, atom.fid))
                elif receiver is None:
                    out.append(atom)
                elif kind == "property":
                    return self.call(atoms([BoundMethod(receiver, atom.fid)]), Args([], {}, False),
                                     None)
                else:
                    out.append(BoundMethod(receiver, atom.fid))
            else:
                out.append(atom)
        return atoms(out)

    def store_attr(self, target: Value, attr: str, value: Value) -> None:
        for atom in target:
            if isinstance(atom, Obj):
                self.an.write(("a", atom.site, attr), value)
            elif isinstance(atom, ClassAtom):
                self.an.write(("k", atom.cid, attr), value)
            elif isinstance(atom, ModuleAtom):
                self.an.write(("g", atom.name, attr), value)

    # -- classes ----------------------------------------------------------------------------
    def user_bases(self, cid: int) -> list[int]:
        value = self.an.heap.get(("bases", cid), BOTTOM)
        return [a.cid for a in _flatten_bases(value) if isinstance(a, ClassAtom)]

    def library_bases(self, cid: int) -> list[str]:
        return [a.qualname for a in self.mro(ClassAtom(cid)) if isinstance(a, Extern)]

    def mro(self, cls: Atom, _seen: frozenset = frozenset()) -> list[Atom]:
        """C3 linearisation over user classes (bases as analysed) and modelled library classes."""
        if isinstance(cls, Extern):
            return [Extern(q) for q in self.lib.mro(cls.qualname)]
        if not isinstance(cls, ClassAtom) or cls in _seen:
            return []
        key = ("bases", cls.cid)
        bases_value = self.an.read(key, self.frame.task) if self.frame else \
            self.an.heap.get(key, BOTTOM)
        bases = _flatten_bases(bases_value)
        seqs = [self.mro(b, _seen | {cls}) for b in bases] + [bases]
        return [cls] + _c3_merge(seqs)

    # =====================================================================================
    # calls
    # =====================================================================================
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
        if func.is_top:
            self._escape(args)
            return TOP
        out = BOTTOM
        for atom in sorted(func, key=repr):
            out = out.join(self._call_atom(atom, args, node))
        return out

    def _escape(self, args: "Args") -> None:
        """Callables passed to unknown code may be called by it: analyse them as entries."""
        for value in list(args.pos) + list(args.kw.values()):
            for atom in value:
                if isinstance(atom, (FuncAtom, BoundMethod)):
                    self.schedule_callback(atom)

    def _call_atom(self, atom: Atom, args: "Args", node) -> Value:
        if isinstance(atom, FuncAtom):
            return self.call_user(atom.fid, None, args)
        if isinstance(atom, BoundMethod):
            return self.call_user(atom.fid, atom.receiver, args)
        if isinstance(atom, ClassAtom):
            return self.instantiate(atom, args, node)
        if isinstance(atom, Extern):
            return self.call_extern(atom.qualname, args, node)
        if isinstance(atom, ExternBound):
            return self.call_bound_extern(atom, args, node)
        return TOP

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
            ctx = tuple(TOP if v.is_bottom else v for v in
                        self._bind_loose(func, receiver))
        return ctx

    def _bind_loose(self, func: Function, receiver: Atom | None) -> list[Value]:
        names = self.param_names(func)
        first = [atoms([receiver])] if receiver is not None else []
        return first + [TOP] * (len(names) - len(first))

    def call_user(self, fid: int, receiver: Atom | None, args: "Args") -> Value:
        func = self.program.functions[fid]
        ctx = self.bind_user(func, receiver, args)
        if ctx is None:
            return BOTTOM
        return self.an.call_summary(fid, ctx, self.frame.task)

    def schedule_callback(self, atom: Atom) -> None:
        if isinstance(atom, FuncAtom):
            self.an.schedule(self.an.function_task(atom.fid, self.default_context(atom.fid, None)))
        elif isinstance(atom, BoundMethod):
            self.an.schedule(self.an.function_task(
                atom.fid, self.default_context(atom.fid, atom.receiver)))

    def instantiate(self, cls: ClassAtom, args: "Args", node) -> Value:
        obj = Obj(self._site(node), cls)
        self.an.allocated.add(cls.cid)
        self.construct(obj, args, node)
        return atoms([obj])

    def construct(self, obj: Obj, args: "Args", node) -> None:
        init = self.class_attr(self.mro(obj.cls), "__init__", obj)
        if init is not None:
            self.call(init, args, node)
        for lib_cls in [c.qualname for c in self.mro(obj.cls) if isinstance(c, Extern)]:
            for name in self.lib.called_methods(lib_cls):
                method = self.class_attr(self.mro(obj.cls), name, obj)
                for atom in method or ():
                    if isinstance(atom, BoundMethod):
                        self.schedule_callback(atom)

    def instantiate_entry(self, cid: int) -> None:
        """Analyse a class nothing instantiates, as if a library created it with unknown arguments."""
        klass = self.program.classes[cid]
        obj = Obj(f"entry:{klass.module.path}:{klass.qualname}", ClassAtom(cid))
        self.an.allocated.add(cid)
        # Lookups need a frame; the class's module top level is the task that re-runs
        # (harmlessly) if what they read grows.
        outer, self.frame = self.frame, Frame(("mod", klass.module.name, ()), klass.module)
        try:
            self._schedule_entry(obj, cid)
        finally:
            self.frame = outer

    def _schedule_entry(self, obj: Obj, cid: int) -> None:
        init = self.class_attr(self.mro(obj.cls), "__init__", obj)
        for atom in init or ():
            if isinstance(atom, BoundMethod):
                self.schedule_callback(atom)
        for lib_cls in self.library_bases(cid):
            for name in self.lib.called_methods(lib_cls):
                for atom in self.class_attr(self.mro(obj.cls), name, obj) or ():
                    if isinstance(atom, BoundMethod):
                        self.schedule_callback(atom)

    def _site(self, node) -> str:
        line = getattr(node, "lineno", 0)
        col = getattr(node, "col_offset", 0)
        return f"{self.frame.module.path}:{line}:{col}"

    # -- library code ---------------------------------------------------------------------------
    def call_extern(self, qualname: str, args: "Args", node) -> Value:
        if qualname.startswith("builtins."):
            return self.call_builtin(qualname[len("builtins."):], args, node)
        owner, _, method = qualname.rpartition(".")
        fn = self.lib.functions.get(qualname) or (
            self.lib.method(owner, method) if owner in self.lib.classes else None)
        if fn is not None:  # a function, or a method called on the class (self passed explicitly)
            return self.apply_model(fn, None, args, node)
        if qualname in self.lib.classes:
            if self.lib.class_flag(qualname, "record"):
                init = self.lib.method(qualname, "__init__")
                bound = self.bind_model(init, None, args) if init else {}
                return atoms([Record(qualname, tuple(sorted(bound.items())))])
            obj = Obj(self._site(node), Extern(qualname))
            init = self.lib.method(qualname, "__init__")
            if init is not None:
                self.apply_model(init, obj, args, node)
            return atoms([obj])
        self._escape(args)
        last = qualname.rsplit(".", 1)[-1]
        if last[:1].isupper():
            return atoms([Obj(self._site(node), Extern(qualname))])
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
        return self.apply_model(model, atom.receiver, args, node)

    def bind_model(self, model: FunctionModel, receiver: Atom | None, args: "Args") -> dict:
        """Arguments of a library call by parameter name (⊥ arguments count as unknown)."""
        params = model.signature.params
        pos = ([atoms([receiver])] if receiver is not None else []) + list(args.pos)
        bound: dict[str, Value] = {}
        positional = [p for p in params if p.kind == "pos"]
        for param, value in zip(positional, pos):
            bound[param.name] = value
        extra = pos[len(positional):]
        for param in params:
            if param.kind == "varargs":
                bound[param.name] = atoms([Seq("tuple", tuple(extra))])
            elif param.kind == "varkw":
                bound[param.name] = atoms([DictAtom(tuple(
                    (const(k), v) for k, v in sorted(args.kw.items())))])
            elif param.name in args.kw:
                bound[param.name] = args.kw[param.name]
            elif param.name not in bound:
                bound[param.name] = TOP if args.star or param.default is None else param.default
        return {k: (TOP if v.is_bottom else v) for k, v in bound.items()}

    def apply_model(self, model: FunctionModel, receiver: Atom | None, args: "Args", node) -> Value:
        bound = self.bind_model(model, receiver, args)
        result = self.model_return(model.returns, bound, receiver, node)
        bound["@return"] = result
        frame = self.frame
        for index, spec in enumerate(model.effects):
            values = tuple((name, self.ref(ref, bound, receiver)) for name, ref in spec.args)
            key = (id(node), model.qualname, index)
            frame.effects[key] = Effect(
                spec.kind, values, frame.module.path, getattr(node, "lineno", 0),
                frame.module.column(node) if node is not None else 0,
                frame.cls is None and frame.block not in frame.dominators,
                frame.func.qualname if frame.func else "<module>")
        for store in model.stores:
            value = self.ref(store.value, bound, receiver)
            for key in self.format_keys(store.key, bound):
                for atom in bound.get(store.on, TOP):
                    if isinstance(atom, Obj):
                        self.an.write(("a", atom.site, key), value)
        for name in model.callbacks:
            for atom in bound.get(name, BOTTOM):
                self.schedule_callback(atom)
        return result

    def model_return(self, spec: ReturnSpec, bound: dict, receiver: Atom | None, node) -> Value:
        if spec.how == "instance":
            qualname = self.lib.canonical(spec.data)
            return atoms([Obj(self._site(node), Extern(qualname))])
        if spec.how == "record":
            fields = tuple((k, self.ref(r, bound, receiver)) for k, r in spec.fields)
            return atoms([Record(spec.data, fields)])
        if spec.how == "ref":
            return self.ref(spec.data, bound, receiver)
        return TOP

    def ref(self, ref: Ref, bound: dict, receiver: Atom | None) -> Value:
        if ref.how == "arg":
            return bound.get(ref.data, TOP)
        if ref.how == "const":
            return ref.data
        if ref.how == "overridable":
            return soften(bound.get(ref.data, TOP))
        if ref.how == "format":
            keys = self.format_keys(ref.data, bound)
            return atoms(Const.of(k) for k in keys) if keys else TOP
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
        if name in PURE_BUILTINS and not args.kw and not args.star:
            if name == "str" and not pos:
                return const("")
            if pos and all(v.consts() is not None for v in pos):
                return fold(PURE_BUILTINS[name], list(pos))
            if name == "len":
                return TOP
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
            return atoms([Coll("list", atoms([Seq("tuple", (TOP, self.iter_elem(pos[0])))]))])
        if name == "zip" and pos:
            return atoms([Coll("list", atoms([Seq("tuple", tuple(self.iter_elem(p) for p in pos))]))])
        if name == "dict":
            if args.kw and not pos:
                return atoms([DictAtom(tuple((const(k), v) for k, v in args.kw.items()))])
            return atoms([Coll("dict", TOP)])
        if name in ("isinstance", "issubclass", "hasattr", "callable"):
            return _BOOLS
        if name == "getattr" and len(pos) >= 2:
            names = pos[1].strings()
            if names:
                out = join_all(self.load_attr(pos[0], n) for n in names)
                return out.join(pos[2]) if len(pos) > 2 else out
            return TOP
        if name == "setattr" and len(pos) == 3:
            for attr in pos[1].strings() or ():
                self.store_attr(pos[0], attr, pos[2])
            return const(None)
        if name == "print":
            return const(None)
        self._escape(args)
        return TOP

    def call_str(self, receiver: Const, name: str, args: "Args") -> Value:
        recv = atoms([receiver])
        if name == "format":
            names = sorted(args.kw)
            pools = [recv] + list(args.pos) + [args.kw[k] for k in names]
            n = len(args.pos)
            return fold(lambda s, *v: s.format(*v[:n], **dict(zip(names, v[n:]))), pools)
        if name == "join" and args.pos:
            out = BOTTOM
            for atom in args.pos[0]:
                if not isinstance(atom, Seq):
                    return TOP
                out = out.join(fold(lambda s, *parts: s.join(parts), [recv, *atom.items]))
            return out if not args.pos[0].is_top else TOP
        if args.kw or args.star:
            return TOP
        return call_str_method(name, recv, list(args.pos))

    def call_container(self, receiver: Atom, name: str, args: "Args") -> Value:
        if isinstance(receiver, DictAtom):
            keys = join_all(k for k, _ in receiver.items)
            values = join_all(v for _, v in receiver.items)
            if name == "get":
                default = args.pos[1] if len(args.pos) > 1 else const(None)
                return self._subscript(receiver, args.pos[0] if args.pos else TOP).join(default)
            if name == "items":
                return atoms([Coll("list", atoms([Seq("tuple", (keys, values))]))])
            if name == "keys":
                return atoms([Coll("list", keys)])
            if name == "values":
                return atoms([Coll("list", values)])
        if name in ("copy",):
            return atoms([receiver])
        if name in ("append", "extend", "insert", "add", "update", "clear", "remove"):
            return const(None)
        return TOP

    # -- helpers ------------------------------------------------------------------------------
    def iter_elem(self, value: Value) -> Value:
        if value.is_top:
            return TOP
        out = BOTTOM
        for atom in value:
            if isinstance(atom, Seq):
                out = out.join(join_all(atom.items))
            elif isinstance(atom, Coll):
                out = out.join(atom.elem)
            elif isinstance(atom, DictAtom):
                out = out.join(join_all(k for k, _ in atom.items))
            elif isinstance(atom, Const) and isinstance(atom.value, str):
                out = out.join(fold(lambda s: s, [atoms([atom])]) if len(atom.value) == 1 else TOP)
            else:
                return TOP
        return out

    @staticmethod
    def truth(value: Value, by_default: bool = True) -> bool | None:
        """Python truthiness if the value decides it, else ``None``.

        A *soft* value (an overridable default) decides value choices
        (``a if opt else b`` names what runs by default) but not control flow: code
        under ``if opt:`` exists in some configuration, so both branches are explored.
        """
        if value.is_top or value.is_bottom or (value.soft and not by_default):
            return None
        seen = set()
        for atom in value:
            if isinstance(atom, Const):
                seen.add(bool(atom.value))
            elif isinstance(atom, Seq):
                seen.add(bool(atom.items))
            elif isinstance(atom, (FuncAtom, BoundMethod, ClassAtom, ModuleAtom, ExternBound)):
                seen.add(True)
            else:
                return None
            if len(seen) > 1:
                return None
        return seen.pop()


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


#: Filters usable in library-model key templates (``{param|filter}``).
KEY_FILTERS = {"argparse_dest": _argparse_dest}


@dataclass(frozen=True)
class Args:
    """Evaluated call arguments; ``star`` means some positions/keywords are unknown."""

    pos: list
    kw: dict
    star: bool


def _with_field(holder: Value, name: str, value: Value) -> Value:
    out = []
    for atom in holder:
        if isinstance(atom, Record):
            fields = dict(atom.fields)
            fields[name] = value
            atom = Record(atom.qualname, tuple(sorted(fields.items())))
        out.append(atom)
    return atoms(out, holder.soft)


def _raise():
    raise ValueError


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
        else:
            out[name] = prev.widen(value) if widen else prev.join(value)
    return out


def _const_tuples(value: Value) -> list[tuple] | None:
    """Concrete tuples for a value whose atoms are tuples of constants (for ``%`` formatting)."""
    if value.is_top:
        return None
    out: list[tuple] = []
    for atom in value:
        if not isinstance(atom, Seq):
            return None
        pools = [v.consts() for v in atom.items]
        if any(p is None for p in pools):
            return None
        for combo in itertools.product(*pools):
            out.append(tuple(combo))
            if len(out) > MAX_ATOMS:
                return None
    return out


def _flatten_bases(value: Value) -> list[Atom]:
    """Base classes in source order from the analysed ``(base, …)`` tuples of a class."""
    out: list[Atom] = []
    for seq in sorted((a for a in value if isinstance(a, Seq)), key=repr):
        for item in seq.items:
            for atom in sorted(item, key=repr):
                if isinstance(atom, (ClassAtom, Extern)) and atom not in out:
                    out.append(atom)
    return out


def _c3_merge(seqs: list[list[Atom]]) -> list[Atom]:
    seqs = [list(s) for s in seqs if s]
    out: list[Atom] = []
    while seqs:
        for seq in seqs:
            head = seq[0]
            if not any(head in s[1:] for s in seqs):
                break
        else:  # inconsistent hierarchy: fall back to depth-first order
            for seq in seqs:
                out.extend(x for x in seq if x not in out)
            return out
        out.append(head)
        seqs = [[x for x in s if x != head] for s in seqs]
        seqs = [s for s in seqs if s]
    return out
