"""Transfer functions of expressions: what each Python expression evaluates to over the value lattice.

Constants fold with Python's own operators (:mod:`.folding`); containers keep their
shape; comprehensions are evaluated inline; calls are delegated to :mod:`.calls`.
"""
from __future__ import annotations

import ast
import itertools
from typing import Callable

from .folding import BINOPS, CMPOPS, SAME_TEXT, UNARYOPS, fold, fold_text
from .calls import Args
from .containers import MUTATORS, may_be_filled_elsewhere, mutated
from .enums import is_member_site
from .exclusion import narrow
from .rows import LoopRows, rows_of, user_call_per_row
from .values import (BOOLS, BOTTOM, MAX_ATOMS, TOP, Atom, BoundMethod, ClassAtom, Coll, Const,
                     DictAtom, Extern, ExternBound, FuncAtom, ModuleAtom, Obj, Seq, Value, atoms,
                     const, join_all, joined, soften)


class ExpressionSemantics:
    """Expression evaluation, mixed into :class:`~.interpreter.Interpreter`."""

    #: Node type → its ``e_`` method (``None``: not modelled, ⊤), per class: one dict lookup
    #: per evaluation instead of building the method's name and looking it up by string.
    _evaluators: dict[type, Callable | None] = {}

    def __init_subclass__(cls, **kwargs) -> None:
        super().__init_subclass__(**kwargs)
        cls._evaluators = {}

    def eval(self, node: ast.expr) -> Value:
        kind = type(node)
        try:
            method = self._evaluators[kind]
        except KeyError:
            method = self._evaluators[kind] = getattr(type(self), "e_" + kind.__name__, None)
        if method is None:
            return TOP
        return method(self, node)

    def e_Constant(self, node: ast.Constant) -> Value:
        return const(node.value)

    def e_Name(self, node: ast.Name) -> Value:
        return self.load_name(node.id)

    def e_Attribute(self, node: ast.Attribute) -> Value:
        return self.attribute_of(node, self.eval(node.value))

    def attribute_of(self, node: ast.Attribute, holder: Value) -> Value:
        """The attribute ``node`` reads of ``holder`` (what ``node.value`` evaluated to)."""
        self.record_attribute_load(node, holder)
        remembered = self.remembered_attribute(node)
        return remembered if remembered is not None else self.load_attr(holder, node.attr)

    def e_NamedExpr(self, node: ast.NamedExpr) -> Value:
        value = self.eval(node.value)
        self.assign(node.target, value)
        return value

    def e_JoinedStr(self, node: ast.JoinedStr) -> Value:
        parts = []
        pieces = []  # the parts as text, an input's value as it is when formatted plainly
        for part in node.values:
            if isinstance(part, ast.Constant):
                parts.append(const(str(part.value)))
                pieces.append(parts[-1])
            elif isinstance(part, ast.FormattedValue):
                value = self.eval(part.value)
                plain = part.conversion in (-1, ord("s")) and part.format_spec is None
                if part.conversion in (ord("r"), ord("a")):
                    value = fold(repr, [value])
                spec = self.eval(part.format_spec) if part.format_spec else const("")
                parts.append(fold_text(format, [value, spec]))
                pieces.append(value if plain else parts[-1])
            else:
                parts.append(TOP)
                pieces.append(TOP)
        return joined(fold_text(lambda *p: "".join(p), parts), pieces)

    def e_BinOp(self, node: ast.BinOp) -> Value:
        return self.binop(node.op, self.eval(node.left), self.eval(node.right))

    def binop(self, op: ast.operator, left: Value, right: Value) -> Value:
        if left.is_bottom or right.is_bottom:
            return BOTTOM
        fn = BINOPS.get(type(op))
        if fn is None:
            return TOP
        if isinstance(op, ast.Mod) and right.consts() is None and not right.hints:
            tuples = _const_tuples(right)
            if tuples is None:
                return TOP
            return fold(fn, [left, atoms(Const("tuple", t) for t in tuples)])
        if isinstance(op, ast.Add) and left.consts() is None:
            items = [a for a in left] + [a for a in right]
            if items and all(isinstance(a, Seq) for a in items) and len(items) == 2:
                a, b = items
                return atoms([Seq(a.kind, a.items + b.items)])
        if isinstance(op, ast.Add):
            return joined(fold_text(fn, [left, right]), [left, right])
        return fold_text(fn, [left, right]) if isinstance(op, ast.Mod) else fold(fn, [left, right])

    def e_UnaryOp(self, node: ast.UnaryOp) -> Value:
        value = self.eval(node.operand)
        if isinstance(node.op, ast.Not):
            decided = self.truth(value)
            return BOOLS if decided is None else const(not decided)
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
        return result if result is not None else BOOLS

    def compare(self, op: ast.cmpop, left: Value, right: Value) -> Value:
        """``left op right``; decided on an overridable default (``args.mode not in (...)``,
        ``args.mode`` being argparse's ``None`` default), the answer is one too: it names what
        runs by default but never decides a branch (a required argument is never its default)."""
        result = self._compare(op, left, right)
        return soften(result) if left.soft or right.soft or _holds_soft(right) else result

    def _compare(self, op: ast.cmpop, left: Value, right: Value) -> Value:
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
                    elif isinstance(a, Obj) and isinstance(b, Obj) and is_member_site(a.site) \
                            and is_member_site(b.site):
                        out.add((a.site == b.site) != negate)
                    elif isinstance(a, Const) != isinstance(b, Const) and \
                            None in (getattr(a, "value", 0), getattr(b, "value", 0)):
                        out.add(negate)  # an object is never None
                    else:
                        out.update((True, False))
            return atoms(Const.of(x) for x in out)
        if isinstance(op, (ast.In, ast.NotIn)) and not right.is_top and (
                left.consts() is not None or _member_sites(left) is not None):
            return _membership(left, right, negate=isinstance(op, ast.NotIn))
        return BOOLS

    def e_IfExp(self, node: ast.IfExp) -> Value:
        test = self.eval(node.test)
        decided = self.truth(test)
        if decided is None:
            return self._in_branch(node.test, node.body, True).join(
                self._in_branch(node.test, node.orelse, False))
        chosen = self.eval(node.body if decided else node.orelse)
        # Chosen by an overridable default (``None if args.trace is None else path``): what
        # runs by default, itself only a default, so a later ``if`` on it explores both ways.
        return soften(chosen) if test.soft else chosen

    def _in_branch(self, test: ast.expr, expr: ast.expr, holds: bool) -> Value:
        """``expr`` where ``test`` evaluated to ``holds`` (``'/' + ns + '/odom' if ns else
        '/odom'``): without the constants the test rules out there (:mod:`.exclusion`). Only
        for a pure test and branch, which write nothing the environment would have to keep."""
        frame = self.frame
        env, overlays = frame.env, frame.comp
        if not (self._writes_nothing(test) and self._writes_nothing(expr)):
            return self.eval(expr)
        *inner, frame.env = narrow([*reversed(overlays), env], self._ruled_out(test, holds), frame.narrowed)
        frame.comp = inner[::-1]  # a comprehension's variables: ``'/' + r if r else '/'`` for r in …
        try:
            return self.eval(expr)
        finally:
            frame.env, frame.comp = env, overlays

    def e_Tuple(self, node: ast.Tuple | ast.List) -> Value:
        kind = "tuple" if isinstance(node, ast.Tuple) else "list"
        items = []
        for elt in node.elts:
            if isinstance(elt, ast.Starred):
                seq = _only(self.eval(elt.value), Seq)
                if seq is None:
                    return atoms([Coll(kind, TOP)])
                items.extend(seq.items)
                continue
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
        return self.e_subscript_value(self.eval(node.value), self.eval(node.slice))

    def e_subscript_value(self, container: Value, index: Value) -> Value:
        """``container[index]``."""
        if container.is_top or all(may_be_filled_elsewhere(a) for a in container):
            return TOP  # only ever seen empty here: what fills it is not seen (as iter_elem)
        out = BOTTOM
        for atom in container:
            out = out.join(self._subscript(atom, index))
        return self.element_of(container, out)

    @staticmethod
    def element_of(container: Value, element: Value) -> Value:
        """What an element read from ``container`` is: a collection supplied from outside (a
        parameter's list) or a default the run may override holds its default's elements at
        most, so they stay names beside the unknown rest (as ``iter_elem``) or overridable
        defaults, and decide no branch (``flags[0]`` of a parameter declared ``[False]``)."""
        if container.origin is not None:
            return TOP.join(element)
        return soften(element) if container.soft else element

    def _call_per_row(self, node: ast.Call) -> Value | None:
        """A creation call in the body of a loop over a written-out table, evaluated once per
        row with the loop variables its arguments read bound to that row's values, so that
        each entity gets its own name, type and callback (:mod:`.rows`); likewise a
        ``setattr`` whose name is such a variable, so that each key gets its own value (a
        table longer than a value holds would leave the name unknown). ``None`` when the
        call is not one (evaluated once, as usual)."""
        frame = self.frame
        arguments = [*node.args, *(kw.value for kw in node.keywords)]
        setter = self._is_setattr(node)
        if setter:  # ``setattr(cfg, key, node.get_parameter(key).value)``: split by the name
            arguments = node.args[:2]
        if not arguments or not all(self._writes_nothing(arg) for arg in arguments):
            return None
        named = arguments[1:] if setter else arguments  # a setter is split by its name alone
        read = {n.id for arg in named for n in ast.walk(arg) if isinstance(n, ast.Name)}
        best: tuple[int, LoopRows, list[int]] | None = None
        for loop, table in frame.loop_rows.items():
            used = read.intersection(table.names)
            reaching = self._reaching_rows(table) if used else None
            if reaching is not None and (best is None or len(used) > len(read.intersection(best[1].names))):
                best = (loop, table, reaching)
        if best is None:
            return None
        func = self.eval(node.func)
        paired = len(read.intersection(best[1].names))
        if not (setter or self._creates(func) or user_call_per_row(func, paired, len(best[2]))):
            return None
        loop, table, reaching = best
        holders = [self._holder(name) for name in table.names]
        saved = [holder[name] for holder, name in zip(holders, table.names)]
        out = BOTTOM
        try:
            for index in reaching:
                row = table.rows[index]
                for holder, name, value in zip(holders, table.names, row):
                    holder[name] = value
                frame.row = (loop, index)
                out = out.join(self.e_Call(node))
        finally:
            for holder, name, value in zip(holders, table.names, saved):
                holder[name] = value
            frame.row = None
        return out

    def _reaching_rows(self, table: LoopRows) -> list[int] | None:
        """The rows of ``table`` that reach the current operation, while its variables still
        hold what the loop bound them to, or what a branch narrowed that to (``if not
        enabled: continue`` lets only the enabled rows through); ``None`` when a variable
        holds something else (the rows no longer say what it is)."""
        narrowings: list[tuple[int, Value]] = []
        for column, (name, bound) in enumerate(zip(table.names, table.bound)):
            current = self._holder(name).get(name)
            if current == bound:
                continue
            if current is None or self.frame.narrowed.get((name, current)) != bound:
                return None
            narrowings.append((column, current))
        return [index for index, row in enumerate(table.rows)
                if all(row[column].leq(current) for column, current in narrowings)]

    def _is_setattr(self, node: ast.Call) -> bool:
        """``setattr(obj, name, value)`` with the builtin: a store by name, which a loop over
        a written-out table makes once per row (each key with the value the row gives it)."""
        return self.builtin_call(node, "setattr", 3)

    def builtin_call(self, node: ast.expr, name: str, arity: int) -> bool:
        """Whether ``node`` calls the builtin ``name`` (not shadowed) with ``arity`` plain
        positional arguments."""
        return isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == name \
            and len(node.args) == arity and not node.keywords \
            and not any(isinstance(a, ast.Starred) for a in node.args) \
            and self.load_name(name) == atoms([Extern(f"builtins.{name}")])

    def _holder(self, name: str) -> dict[str, Value]:
        """Where ``name`` lives here: the innermost comprehension binding it, else the frame."""
        for overlay in reversed(self.frame.comp):
            if name in overlay:
                return overlay
        return self.frame.env

    def _creates(self, func: Value) -> bool:
        """Whether calling ``func`` runs a library model with effects (``create_service``, an
        ``ActionServer``): only those are split per row, not the workspace's own functions
        (each row would be a calling context of its own)."""
        if func.is_top or func.is_bottom:
            return False
        for atom in func:
            qualname = atom.qualname if isinstance(atom, (Extern, ExternBound)) else None
            if qualname is None:
                return False
            owner, _, method = qualname.rpartition(".")
            model = self.lib.functions.get(qualname) or self.lib.method(owner, method) \
                or self.lib.method(qualname, "__init__")
            if model is None or not model.effects:
                return False
        return True

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
            members = _member_sites(index)
            if keys is None and members is None:
                return join_all(v for _, v in atom.items)
            out = BOTTOM
            for k, v in atom.items:
                if members is not None:  # a table keyed by enum members: by identity
                    found = _member_sites(k)
                    if not k.is_bottom and (found is None or found & members):
                        out = out.join(v)
                    continue
                kc = k.consts()
                if kc is None or any(x in kc for x in keys):
                    out = out.join(v)
            return out
        if isinstance(atom, Const) and isinstance(atom.value, (str, bytes, tuple)):
            return fold(lambda s, i: s[i], [atoms([atom]), index])
        if isinstance(atom, ClassAtom) and self.is_generic_alias(atom):
            return atoms([atom])
        return TOP

    def e_Starred(self, node: ast.Starred) -> Value:
        return self.eval(node.value)

    def e_Lambda(self, node: ast.Lambda) -> Value:
        for default in node.args.defaults:
            self.eval(default)
        return atoms([FuncAtom(self.program.fid_of[id(node)])])

    def e_Await(self, node: ast.Await) -> Value:
        value = self.eval(node.value)
        self.forget_attributes()  # other coroutines run meanwhile
        return value

    def e_Yield(self, node: ast.Yield) -> Value:
        """What the generator yields is kept per function (``("yield", fid)``): a framework
        that takes a generator's first value (a pytest fixture) reads it there; and per task
        (``("yield", task)``), for the caller of a ``@contextmanager`` function, whose
        ``with … as x`` gets what that call's generator yields, not every call's."""
        value = self.eval(node.value) if node.value is not None else const(None)
        func = self.frame.func
        if func is not None and isinstance(node, ast.Yield):
            self.an.write(("yield", func.fid), value)
            self.an.write(("yield", self.frame.task), value)
        self.forget_attributes()  # the generator's consumer runs meanwhile
        return TOP

    e_YieldFrom = e_Yield

    def e_ListComp(self, node) -> Value:
        overlay: dict[str, Value] = {}
        self.frame.comp.append(overlay)
        try:
            for gen in node.generators:
                iterable = self.eval(gen.iter)
                elem = self.iter_elem(iterable)
                for name_node in ast.walk(gen.target):
                    if isinstance(name_node, ast.Name):
                        overlay[name_node.id] = TOP
                self.assign(gen.target, elem)
                found = rows_of(gen.target, iterable)
                if found is not None:  # ``{n: node.create_publisher(t, n, 10) for n, t in TABLE}``
                    self.frame.loop_rows[id(gen)] = LoopRows(
                        found[0], tuple(overlay[n] for n in found[0]), found[1])
                for cond in gen.ifs:
                    self.eval(cond)
            if isinstance(node, ast.DictComp):
                self.eval(node.key)
                elem = self.eval(node.value)
            else:
                elem = self.eval(node.elt)
        finally:
            self.frame.comp.pop()
            for gen in node.generators:
                self.frame.loop_rows.pop(id(gen), None)
        kind = {ast.ListComp: "list", ast.SetComp: "set", ast.DictComp: "dict"}.get(
            type(node), "gen")
        return atoms([Coll(kind, elem)])

    e_SetComp = e_DictComp = e_GeneratorExp = e_ListComp

    def e_Call(self, node: ast.Call) -> Value:
        if self.frame.loop_rows and self.frame.row is None:
            per_row = self._call_per_row(node)
            if per_row is not None:
                return per_row
        self.an.reached_calls.setdefault(self.frame.task, set()).add(
            (self.frame.module.path, node.lineno, node.col_offset))
        if isinstance(node.func, ast.Name) and node.func.id == "super" \
                and self.load_name("super") == atoms([Extern("builtins.super")]):
            return self.super_value(node)
        holder = BOTTOM  # what a method is called on
        if isinstance(node.func, ast.Attribute):
            holder = self.eval(node.func.value)
            if node.func.attr in SAME_TEXT and not node.args and not node.keywords and holder.origin is not None \
                    and all(isinstance(c, str) and getattr(c, node.func.attr)() == c for c in holder.consts() or ()):
                return holder  # still the setting, named by its origin (its known texts unchanged)
            func = self.attribute_of(node.func, holder)
        else:
            func = self.eval(node.func)
        args: list[Value] = []
        star = False
        for arg in node.args:
            if isinstance(arg, ast.Starred):
                seq = _only(self.eval(arg.value), Seq)
                if seq is None:
                    star = True
                else:
                    args.extend(seq.items)
            else:
                args.append(self.eval(arg))
        kwargs: dict[str, Value] = {}
        for kw in node.keywords:
            value = self.eval(kw.value)
            if kw.arg is not None:
                kwargs[kw.arg] = value
            else:
                mapping = _only(value, DictAtom)
                if mapping is not None and all(len(k.strings() or ()) == 1 for k, _ in mapping.items):
                    kwargs.update((k.strings()[0], v) for k, v in mapping.items)
                else:
                    star = True
        result = self.call(func, Args(args, kwargs, star), node)
        if holder.soft and all(isinstance(a, Const) and isinstance(a.value, str) for a in holder):
            # ``str(param.value).strip().lower()``: text computed from an overridable default
            # is one too (a string method's bound receiver keeps no mark of its own).
            result = soften(result)
        target = node.func
        if isinstance(target, ast.Attribute) and target.attr == "get" and holder.is_top \
                and len(args) == 2 and not kwargs and not star:
            # ``config.get('cmd_topic', '/cmd_vel')`` on a mapping read from a file: the
            # default where the key is missing, unknown otherwise (the default kept beside it).
            result = result.join(args[1])
        if isinstance(target, ast.Attribute) and target.attr in MUTATORS and not star \
                and isinstance(target.value, (ast.Name, ast.Attribute)):
            holder = self.eval(target.value)
            if any(isinstance(a, (Seq, Coll, DictAtom)) for a in holder):
                # Filled in place: rebind what the container was reached through.
                self.assign(target.value, mutated(holder, target.attr, args, self.iter_elem))
        return result

    # -- helpers ------------------------------------------------------------------------------
    def iter_elem(self, value: Value) -> Value:
        if value.is_top:
            return TOP
        if all(may_be_filled_elsewhere(a) for a in value):
            return TOP  # only ever seen empty here: what fills it is not seen
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
            elif isinstance(atom, ClassAtom) and self.enum_members(atom) is not None:
                for name in self.enum_members(atom):  # ``for topic in Topics:``
                    out = out.join(self.enum_member(atom, name))
            else:
                return TOP
        return self.element_of(value, out)

    def truth(self, value: Value, by_default: bool = True) -> bool | None:
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
            elif isinstance(atom, Seq) and not may_be_filled_elsewhere(atom):
                seen.add(bool(atom.items))
            elif isinstance(atom, (FuncAtom, BoundMethod, ClassAtom, ModuleAtom, ExternBound)) \
                    or (isinstance(atom, Obj) and isinstance(atom.cls, Extern)
                        and self.lib.instance_is_true(atom.cls.qualname)):
                seen.add(True)
            else:
                return None
            if len(seen) > 1:
                return None
        return seen.pop()


def _only(value: Value, kind: type):
    """The value's single atom if it is exactly one atom of ``kind`` (``*x`` / ``**x`` unpacking)."""
    items = list(value)
    return items[0] if len(items) == 1 and isinstance(items[0], kind) else None


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


def _membership(left: Value, right: Value, negate: bool) -> Value:
    """``left in right`` for constants (or enum members) in tuples/lists of known length
    (``msg.__module__ in ('a', 'b')``, ``mode in (Mode.SIM, Mode.REPLAY)``): decided where
    every item that could match is a known constant (member)."""
    by_identity = _member_sites(left)
    out: set[bool] = set()
    for container in right:
        if not isinstance(container, Seq):
            return BOOLS
        if by_identity is not None:
            items = [None if (m := _member_sites(item)) is None else sorted(m)
                     for item in container.items]
        else:
            items = [item.consts() for item in container.items]
        for value in sorted(by_identity) if by_identity is not None else left.consts() or ():
            if any(len(item) == 1 and item[0] == value for item in items if item is not None):
                out.add(not negate)
            elif all(item is not None and value not in item for item in items):
                out.add(negate)
            else:
                out.update((True, False))
    return atoms(Const.of(x) for x in out) if out else BOOLS


def _holds_soft(value: Value) -> bool:
    """Whether an item of a known sequence is an overridable default (``x in (args.a, 'b')``)."""
    return any(item.soft for atom in value if isinstance(atom, Seq) for item in atom.items)


def _member_sites(value: Value) -> frozenset[str] | None:
    """The enum members ``value`` may be (their sites), ``None`` unless it is only members."""
    if value.is_top or value.is_bottom or not all(
            isinstance(a, Obj) and is_member_site(a.site) for a in value):
        return None
    return frozenset(a.site for a in value)
