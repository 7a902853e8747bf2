"""What a branch rules out: the constants a local (or an attribute the function just stored,
``self.ns``) cannot be on one way out of a test.

``for ns in ['', 'left', 'right']: if ns: create_publisher(T, '/' + ns + '/y', 10)``: Python
takes the branch only for ``'left'`` and ``'right'``, so the name is never ``'//y'``. Without
this, the analysis evaluates the branch with every constant the local may hold and invents
names the code never makes (a confident wrong name is worse than an unknown one). Likewise
the ``else`` of ``if x == '':``, the way past ``x != c``, ``x is not None``, ``x not in (…)``,
``not x``, an ordering with a number (``if hz > 0:``, also written ``0 < hz``), and each
operand of ``a and b`` (both hold) or ``a or b`` (both fail).

Only constants are ruled out, and the objects a type test tells apart (``isinstance(msg, A)``:
the other branch holds the other message); a value only shrinks: the narrowed value is a
subset of the original, so where the two ways join again the join is the original value
itself (:meth:`.values.Value.join` keeps the larger operand). A setting from outside keeps
its origin; when every default it had is ruled out it is that setting, unknown.
"""
from __future__ import annotations

import ast
import operator
from typing import Callable

from .values import Atom, Const, Value

#: Keeps an atom of a value (``True``) or rules it out.
Keep = Callable[[Atom], bool]
#: A type test (``isinstance(x, C)``): the entry it tests and, per atom, whether it passes
#: (``None``: not known); else ``None``.
TypeTest = Callable[[ast.expr], "tuple[str, Callable[[Atom], bool | None]] | None"]
#: Evaluates a (pure) expression where the test was evaluated.
Evaluate = Callable[[ast.expr], Value]
#: The environment entry an expression reads (a local's name, or the key under which the
#: function remembers an attribute it stored: :mod:`.attrflow`), else ``None``.
Slot = Callable[[ast.expr], "str | None"]
#: Constants compared at most, per test: past it nothing is ruled out.
MAX_RULED_OUT = 16
#: The orderings a test may compare a number with (``if period > 0:``).
ORDERINGS: dict[type, Callable[[object, object], bool]] = {
    ast.Lt: operator.lt, ast.LtE: operator.le, ast.Gt: operator.gt, ast.GtE: operator.ge}
#: The same comparison read from the other side (``0 < period`` is ``period > 0``).
MIRRORED: dict[type, type] = {ast.Lt: ast.Gt, ast.LtE: ast.GtE, ast.Gt: ast.Lt, ast.GtE: ast.LtE,
                              ast.Eq: ast.Eq, ast.NotEq: ast.NotEq}


def ruled_out(test: ast.expr, holds: bool, evaluate: Evaluate, listed: Callable[[Value], list | None],
              slot: Slot, type_test: TypeTest) -> list[tuple[str, Keep]]:
    """For each environment entry ``test`` constrains when it evaluates to ``holds``: its key
    and which of its atoms remain possible. ``listed`` gives the constants a container value
    lists; ``type_test`` reads ``isinstance(x, C)`` (``msg`` one of two message objects: the
    ``else`` of ``isinstance(msg, A)`` publishes the other one)."""
    tested = slot(test)
    if tested is not None:
        return [(tested, _constants(lambda value: bool(value) == holds))]
    typed = type_test(test)
    if typed is not None:
        name, passes = typed
        return [(name, lambda atom: passes(atom) is not (not holds))]
    if isinstance(test, ast.UnaryOp) and isinstance(test.op, ast.Not):
        return ruled_out(test.operand, not holds, evaluate, listed, slot, type_test)
    if isinstance(test, ast.BoolOp) and isinstance(test.op, ast.And) == holds:
        # ``a and b`` holds: both hold; ``a or b`` fails: both fail.
        return [found for operand in test.values
                for found in ruled_out(operand, holds, evaluate, listed, slot, type_test)]
    if isinstance(test, ast.Compare) and len(test.ops) == 1:
        op, right = type(test.ops[0]), test.comparators[0]
        compared = slot(test.left)
        if compared is not None:
            return _compared(compared, op, right, holds, evaluate, listed)
        compared = slot(right)
        if compared is not None and op in MIRRORED:
            return _compared(compared, MIRRORED[op], test.left, holds, evaluate, listed)
    return []


def _constants(keep: Callable[[object], bool]) -> Keep:
    """A rule on constants' values, as a rule on atoms: anything but a constant is kept."""
    return lambda atom: type(atom) is not Const or keep(atom.value)


def _compared(name: str, op: type, right: ast.expr, holds: bool, evaluate: Evaluate,
              listed: Callable[[Value], list | None]) -> list[tuple[str, Keep]]:
    if op in ORDERINGS:
        return _ordered(name, ORDERINGS[op], evaluate(right), holds)
    differs = (op in (ast.Eq, ast.Is, ast.In)) != holds  # the local is *not* what it is compared with
    if not differs or op not in (ast.Eq, ast.NotEq, ast.Is, ast.IsNot, ast.In, ast.NotIn):
        return []
    if op in (ast.Is, ast.IsNot):
        if not (isinstance(right, ast.Constant) and any(right.value is c for c in (None, True, False))):
            return []  # ``is`` compares identity: only the singletons are known to be one object
        singleton = right.value
        return [(name, _constants(lambda value: value is not singleton))]
    other = evaluate(right)
    if other.soft or other.origin is not None:
        return []  # a default the run may replace: what it is compared with is not known
    if op in (ast.In, ast.NotIn):
        excluded = listed(other)
    else:
        consts = other.consts()
        excluded = consts if consts is not None and len(consts) == 1 else None
    if not excluded or len(excluded) > MAX_RULED_OUT:
        return []
    return [(name, _constants(lambda value: not any(_equal(value, c) for c in excluded)))]


def _ordered(name: str, compare: Callable[[object, object], bool], other: Value,
             holds: bool) -> list[tuple[str, Keep]]:
    """``x < c`` and the like, with ``c`` one number the run cannot replace: the numbers on the
    wrong side of it are ruled out (``if period > 0:`` never creates a timer of period 0)."""
    consts = other.consts() if not other.soft and other.origin is None else None
    if consts is None or len(consts) != 1 or not _number(consts[0]):
        return []
    bound = consts[0]
    return [(name, _constants(lambda value: not _number(value) or compare(value, bound) == holds))]


def _number(value: object) -> bool:
    return type(value) in (int, float)


def _equal(value: object, other: object) -> bool:
    try:
        return bool(value == other)
    except Exception:  # a constant's ``==`` never raises; anything else is not ruled out
        return False


def narrowed(value: Value, keep: Keep) -> Value:
    """``value`` without the atoms ``keep`` rules out (itself when it rules none out)."""
    if value.is_top:
        if not value.hints:
            return value
        hints = frozenset(h for h in value.hints if keep(h))
        return value if hints == value.hints else Value(None, hints=hints, origin=value.origin)
    kept = frozenset(a for a in value.atoms if keep(a))
    if kept == value.atoms:
        return value
    if not kept:  # every default ruled out (the branch is not taken by default): unknown
        return Value(None, origin=value.origin)
    return Value(kept, value.soft, origin=value.origin)  # a subset: within the bounds


def narrow(scopes: list[dict], rules: list[tuple[str, Keep]], narrowings: dict) -> list[dict]:
    """``scopes`` (innermost first) with each rule applied to the innermost scope that holds its
    name; a scope that changes is a copy, the others are the same dicts. ``narrowings`` learns
    each narrowed value, as ``(name, narrowed value) -> the value it narrowed`` (the first one
    when a value is narrowed again): a loop over a table still knows which rows it holds."""
    out = list(scopes)
    for name, keep in rules:
        for index, scope in enumerate(out):
            if name not in scope:
                continue
            current = scope[name]
            value = narrowed(current, keep)
            if value is not current:
                if scope is scopes[index]:
                    out[index] = scope = dict(scope)
                scope[name] = value
                narrowings[(name, value)] = narrowings.get((name, current), current)
            break
    return out
