"""Call sites: which calls each analysed task makes, for rules that follow call chains.

The engine records, for every task (a body under one context), each call it made on
its latest run: where (path, line, column), whether the call runs on every normal path
through the body, and what was called — another task of the workspace, or a modelled
library function with its arguments bound by parameter name (and the effects that call
recorded).  Nothing here knows what a library function means; consumers look the
qualified name up in the library model.
"""
from __future__ import annotations

import ast
import itertools
from dataclasses import dataclass, field
from typing import Iterator

from .values import Value


@dataclass(frozen=True)
class CallSite:
    """One call made by a task.

    ``callee`` is ``("task", task)`` for workspace code, ``("lib", qualname)`` for a
    modelled library function or method (``args`` then holds its bound arguments,
    ``"self"`` the receiver, and ``effects`` what the call recorded).
    """

    path: str
    line: int
    column: int
    callee: tuple
    conditional: bool     # runs on some normal paths through the body only
    guarded: bool         # inside a ``try`` that has handlers
    args: tuple[tuple[str, Value], ...] = ()
    effects: tuple = ()
    #: The call expression, for messages only (never compared).
    node: ast.AST | None = field(default=None, compare=False, hash=False, repr=False)
    #: For a modelled library call with effects: the exception classes the ``except``
    #: clauses around it catch, innermost first, by qualified name (``builtins.BaseException``
    #: for a bare ``except:``, ``?`` for a class the analysis cannot name) — what stops an
    #: exception the call raises (a guarded ``get_parameter``).
    caught: tuple[str, ...] = ()
    #: Conditional only on the module's top-level ``__main__`` guard, in a statement its run
    #: as a program always runs, in order (:func:`.main_guard.script_steps`).
    script_step: bool = False

    def arg(self, name: str) -> Value | None:
        for key, value in self.args:
            if key == name:
                return value
        return None

    def text(self) -> str:
        """The called expression as written (``self.client.call``), for messages."""
        func = getattr(self.node, "func", self.node)
        try:
            return ast.unparse(func) if func is not None else "?"
        except (ValueError, RecursionError, AttributeError):
            return "?"


class CallGraph:
    """The calls of every task's latest run (a view over the engine's table)."""

    def __init__(self, calls: dict[tuple, dict[tuple, CallSite]]) -> None:
        self._calls = calls
        self._sorted: dict[tuple, list[CallSite]] = {}
        #: Tasks by function (fid), in ``repr`` order; rebuilt if the table grew since.
        self._by_function: dict[int, list[tuple]] = {}
        self._indexed = -1
        #: Every task in ``repr`` order; rebuilt if the table grew since.
        self._ordered: list[tuple] | None = None

    def tasks(self) -> Iterator[tuple]:
        if self._ordered is None or len(self._ordered) != len(self._calls):
            self._ordered = sorted(self._calls, key=repr)
        return iter(self._ordered)

    def sites(self, task: tuple) -> list[CallSite]:
        """The calls ``task`` makes, in source order."""
        known = self._sorted.get(task)
        if known is None:
            known = self._sorted[task] = _in_source_order(self._calls.get(task, {}).values())
        return known

    def tasks_of(self, fid: int) -> list[tuple]:
        """Every analysed task of function ``fid`` (one per context)."""
        if self._indexed != len(self._calls):
            self._by_function = {}
            for task in sorted((t for t in self._calls if t[0] == "fn"), key=repr):
                self._by_function.setdefault(task[1], []).append(task)
            self._indexed = len(self._calls)
        return list(self._by_function.get(fid, ()))


def _place(site: CallSite) -> tuple[int, int]:
    return site.line, site.column


def _in_source_order(sites) -> list[CallSite]:
    """``sites`` sorted by ``(line, column, repr(callee))``: by place, and only the calls tied on
    their place (a call of a union of callees) by the text of the callee — the same order (the
    sort is stable), without rendering every callee."""
    out: list[CallSite] = []
    for _, tied in itertools.groupby(sorted(sites, key=_place), key=_place):
        group = list(tied)
        out += group if len(group) == 1 else sorted(group, key=lambda s: repr(s.callee))
    return out
