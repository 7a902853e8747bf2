"""Where evaluation happens: the task, module, function or class body and block being interpreted."""
from __future__ import annotations

from dataclasses import dataclass, field

from .engine import Task
from .program import Class, Function, Module
from .rows import LoopRows
from .values import BOTTOM, Value

Env = dict  # variable name -> Value


@dataclass
class Frame:
    """Where evaluation currently happens: task, module, function or class body, block."""

    task: Task
    module: Module
    func: Function | None = None
    cls: Class | None = None
    dominators: frozenset[int] = frozenset()
    block: int = 0
    guarded: bool = False  # the current block is inside a try with handlers
    #: The except clauses of the trys around the current block, innermost first.
    catching: tuple = ()
    env: Env = field(default_factory=dict)
    effects: dict = field(default_factory=dict)
    calls: dict = field(default_factory=dict)
    comp: list[dict[str, Value]] = field(default_factory=list)
    ret: Value = BOTTOM
    falls_off: bool = False  # the end of the body is reached without a return statement
    #: The rows of the loops over written-out tables, by loop (id of its binding), while
    #: their variables hold what the loop bound (see :mod:`.rows`).
    loop_rows: dict[int, LoopRows] = field(default_factory=dict)
    #: The row a creation call is being evaluated for: ``(loop, row index)``, else ``None``.
    row: tuple[int, int] | None = None
    #: What branches narrowed locals to (:mod:`.exclusion`): (name, narrowed value) -> the
    #: value it narrowed, so a loop over a table still knows which of its rows reach a branch.
    narrowed: dict[tuple[str, Value], Value] = field(default_factory=dict)
