"""Rows of a loop over a table the code wrote out.

``for name, srv_type, callback in SERVICES: node.create_service(srv_type, name, callback)``
over a list of tuples: the analysis binds each loop variable to the join of its column, so
the call sees every name with every type (the graph cannot pair them and leaves the types
unknown), and a table longer than the atoms a value holds (:data:`~.values.MAX_ATOMS`) is
unknown altogether. Python runs the body once per row, each name with its own type.

A loop whose iterable is a list or tuple of known rows (each as long as the target) keeps
those rows beside the joined binding; a call that creates something and whose arguments
read the loop variables (and call nothing) is then evaluated once per row, with the
variables bound to that row's values (see ``ExpressionSemantics.e_Call``); so is a
``setattr(obj, key, value)`` whose ``key`` is a loop variable (a configuration filled from a
table of parameter defaults), whatever its value calls; and a call of the workspace's own
function that is given several columns of a short table (``wait_for_service(node, name,
srv_type)`` for each row of a name -> type table): each row is then a calling context of
its own, so the function creates each name with its own type.

This module only reads values: which rows a loop target takes. The interpreter binds them.
"""
from __future__ import annotations

import ast
from dataclasses import dataclass

from .values import BoundMethod, FuncAtom, Seq, Value

#: Rows kept per loop at most: past it the joined binding alone is used.
ROW_LIMIT = 64
#: Rows a call of a workspace function is split into at most: each is a calling context, and
#: the contexts a function keeps its arguments in are bounded (see ``Analysis.function_task``).
USER_CALL_ROWS = 8


@dataclass(frozen=True)
class LoopRows:
    """The rows of one loop: the variable names its target binds, the joined values the
    loop bound them to (the rows are used only while the variables still hold those), and
    each row's value per variable."""

    names: tuple[str, ...]
    bound: tuple[Value, ...]
    rows: tuple[tuple[Value, ...], ...]


def target_names(target: ast.AST) -> tuple[str, ...] | None:
    """``x`` or ``a, b, c`` (names only, no starred or nested targets), else ``None``."""
    if isinstance(target, ast.Name):
        return (target.id,)
    if isinstance(target, (ast.Tuple, ast.List)) and target.elts \
            and all(isinstance(e, ast.Name) for e in target.elts):
        return tuple(e.id for e in target.elts)
    return None


def rows_of(target: ast.AST, iterable: Value) -> tuple[tuple[str, ...], tuple[tuple[Value, ...], ...]] | None:
    """The variables ``target`` binds and the rows ``iterable`` gives them, when every
    possibility of ``iterable`` is a sequence of known items and every item unpacks into
    the target (a tuple of its length when the target is a tuple); ``None`` otherwise, and
    for a collection supplied from outside (a list parameter), whose written default lists
    only some of the rows a run may have."""
    names = target_names(target)
    if names is None or iterable.is_top or iterable.is_bottom or iterable.origin is not None:
        return None
    rows: list[tuple[Value, ...]] = []
    for table in iterable:
        if not isinstance(table, Seq):
            return None
        for item in table.items:
            if len(names) == 1:
                rows.append((item,))
                continue
            if item.is_top or item.is_bottom:
                return None
            for row in item:
                if not isinstance(row, Seq) or len(row.items) != len(names):
                    return None
                rows.append(tuple(row.items))
    if not rows or len(rows) > ROW_LIMIT:
        return None
    return names, tuple(dict.fromkeys(rows))


def user_call_per_row(func: Value, columns: int, rows: int) -> bool:
    """Whether a call of ``func`` in a loop over a table, given ``columns`` of its variables,
    is split per row: ``func`` is the workspace's own code, the call pairs several columns
    (a name with its type; one column alone loses nothing to the joined binding) and the
    reaching rows fit the contexts the function keeps."""
    if func.is_top or func.is_bottom or columns < 2 or rows > USER_CALL_ROWS:
        return False
    return all(isinstance(atom, (FuncAtom, BoundMethod)) for atom in func)
