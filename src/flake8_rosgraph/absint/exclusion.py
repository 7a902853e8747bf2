"""What a branch rules out: the constants a local cannot be on one way out of a test.

``for ns in ['', 'left', 'right']: if ns: create_publisher(T, '/' + ns + '/y', 10)``: Python
takes the branch only for ``'left'`` and ``'right'``, so the name is never ``'//y'``. Without
this, the analysis evaluates the branch with every constant the local may hold and invents
names the code never makes (a confident wrong name is worse than an unknown one). Likewise
the ``else`` of ``if x == '':``, the way past ``x != c``, ``x is not None``, ``x not in (…)``,
``not x``, and each operand of ``a and b`` (both hold) or ``a or b`` (both fail).

Only constants are ruled out, never objects or containers, and a value only shrinks: the
narrowed value is a subset of the original, so where the two ways join again the join is the
original value itself (:meth:`.values.Value.join` keeps the larger operand). A setting from
outside keeps its origin; when every default it had is ruled out it is that setting, unknown.
"""
from __future__ import annotations

import ast
from typing import Callable

from .values import Const, Value

#: Keeps a constant (``True``) or rules it out.
Keep = Callable[[object], bool]
#: Evaluates a (pure) expression where the test was evaluated.
Evaluate = Callable[[ast.expr], Value]
#: Constants compared at most, per test: past it nothing is ruled out.
MAX_RULED_OUT = 16


def ruled_out(test: ast.expr, holds: bool, evaluate: Evaluate,
              listed: Callable[[Value], list | None]) -> list[tuple[str, Keep]]:
    """For each local ``test`` constrains when it evaluates to ``holds``: its name and which of
    its constants remain possible. ``listed`` gives the constants a container value lists."""
    if isinstance(test, ast.Name):
        return [(test.id, lambda value: bool(value) == holds)]
    if isinstance(test, ast.UnaryOp) and isinstance(test.op, ast.Not):
        return ruled_out(test.operand, not holds, evaluate, listed)
    if isinstance(test, ast.BoolOp) and isinstance(test.op, ast.And) == holds:
        # ``a and b`` holds: both hold; ``a or b`` fails: both fail.
        return [found for operand in test.values for found in ruled_out(operand, holds, evaluate, listed)]
    if isinstance(test, ast.Compare) and len(test.ops) == 1 and isinstance(test.left, ast.Name):
        return _compared(test.left.id, type(test.ops[0]), test.comparators[0], holds, evaluate, listed)
    return []


def _compared(name: str, op: type, right: ast.expr, holds: bool, evaluate: Evaluate,
              listed: Callable[[Value], list | None]) -> list[tuple[str, Keep]]:
    differs = (op in (ast.Eq, ast.Is, ast.In)) != holds  # the local is *not* what it is compared with
    if not differs or op not in (ast.Eq, ast.NotEq, ast.Is, ast.IsNot, ast.In, ast.NotIn):
        return []
    if op in (ast.Is, ast.IsNot):
        if not (isinstance(right, ast.Constant) and any(right.value is c for c in (None, True, False))):
            return []  # ``is`` compares identity: only the singletons are known to be one object
        singleton = right.value
        return [(name, lambda value: value is not singleton)]
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
    return [(name, lambda value: not any(_equal(value, c) for c in excluded))]


def _equal(value: object, other: object) -> bool:
    try:
        return bool(value == other)
    except Exception:  # a constant's ``==`` never raises; anything else is not ruled out
        return False


def narrowed(value: Value, keep: Keep) -> Value:
    """``value`` without the constants ``keep`` rules out (itself when it rules none out)."""
    if value.is_top:
        if not value.hints:
            return value
        hints = frozenset(h for h in value.hints if keep(h.value))
        return value if hints == value.hints else Value(None, hints=hints, origin=value.origin)
    kept = frozenset(a for a in value.atoms if type(a) is not Const or keep(a.value))
    if kept == value.atoms:
        return value
    if not kept:  # every default ruled out (the branch is not taken by default): unknown
        return Value(None, origin=value.origin)
    return Value(kept, value.soft, origin=value.origin)  # a subset: within the bounds
