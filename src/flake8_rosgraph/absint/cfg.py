"""Control-flow graphs built from the stdlib ``ast``.

One CFG per function body (and per module / class body).  A :class:`Block` holds a
straight-line list of *operations* — plain simple statements (``ast.Assign``,
``ast.Expr``, ``ast.Import``, ``ast.FunctionDef`` …) or the small synthetic
operations below that the structured statements lower to — and its successor edges.
Branch edges carry the test expression and polarity so the engine can prune
branches whose condition is a known constant; ``and`` / ``or`` / ``not`` in a test
are lowered to short-circuit edges.

Approximations, chosen on purpose:
- every statement inside a ``try`` body gets its own block, and each such block has
  exception edges to the handlers (the engine sends both its entry and exit state);
- ``finally`` runs after the normal completion of try/else/handlers; ``return`` /
  ``break`` / ``continue`` that leave a ``try`` go straight to their target;
- a ``match`` case may always fall through to the next one (patterns are not decided).
"""
from __future__ import annotations

import ast
from dataclasses import dataclass, field


# -- synthetic operations --------------------------------------------------------
@dataclass(frozen=True)
class Eval:
    """Evaluate an expression for its effects (branch tests, ``assert``, ``raise``)."""

    expr: ast.expr


@dataclass(frozen=True)
class Bind:
    """Bind ``target`` to a value derived from ``value``: ``how`` is "iter" (an element of
    it), "enter" (``with value as target``), "except" (an exception instance) or "match"
    (a capture of a match pattern)."""

    target: ast.AST
    value: ast.expr | None
    how: str


@dataclass(frozen=True)
class Return:
    value: ast.expr | None


@dataclass(frozen=True)
class Edge:
    target: int
    test: ast.expr | None = None
    polarity: bool = True


@dataclass
class Block:
    id: int
    ops: list = field(default_factory=list)
    succs: list[Edge] = field(default_factory=list)
    exc_succs: tuple[int, ...] = ()
    #: The ``except`` clauses of every ``try`` around the block, innermost first: what an
    #: exception raised here may be caught by.
    catching: tuple[ast.ExceptHandler, ...] = ()


@dataclass
class CFG:
    entry: int
    exit: int
    blocks: dict[int, Block]
    loop_heads: frozenset[int]
    _exit_dominators: frozenset[int] | None = field(default=None, repr=False, compare=False)

    def preds(self, exceptional: bool = True) -> dict[int, list[int]]:
        out: dict[int, list[int]] = {b: [] for b in self.blocks}
        for block in self.blocks.values():
            for edge in block.succs:
                out[edge.target].append(block.id)
            if exceptional:
                for target in block.exc_succs:
                    out[target].append(block.id)
        return out

    def exit_dominators(self) -> frozenset[int]:
        """Blocks on every exception-free path from entry to the normal exit: their
        operations always run unless something raises (an entity created inside
        ``try: … except KeyboardInterrupt:`` is not "conditional"). Classic iterative
        algorithm over the normal edges; computed once per CFG."""
        if self._exit_dominators is None:
            self._exit_dominators = self._compute_exit_dominators()
        return self._exit_dominators

    def _compute_exit_dominators(self) -> frozenset[int]:
        preds = self.preds(exceptional=False)
        order = sorted(self.blocks)
        every = frozenset(order)
        dom = {b: every for b in order}
        dom[self.entry] = frozenset((self.entry,))
        changed = True
        while changed:
            changed = False
            for b in order:
                if b == self.entry:
                    continue
                ps = [dom[p] for p in preds[b]]
                new = (frozenset.intersection(*ps) if ps else every) | {b}
                if new != dom[b]:
                    dom[b] = new
                    changed = True
        return dom[self.exit]


class _Builder:
    def __init__(self) -> None:
        self.blocks: dict[int, Block] = {}
        self.loops: list[tuple[int, int]] = []      # (continue target, break target)
        self.handlers: list[tuple[int, ...]] = []   # handler entries of enclosing trys
        self.catching: tuple[ast.ExceptHandler, ...] = ()  # their except clauses, innermost first
        self.heads: set[int] = set()
        self.exit = -1
        self._temps = 0

    def new(self) -> int:
        bid = len(self.blocks)
        self.blocks[bid] = Block(bid, exc_succs=self.handlers[-1] if self.handlers else (),
                                 catching=self.catching)
        return bid

    def link(self, src: int | None, dst: int, test: ast.expr | None = None,
             polarity: bool = True) -> None:
        if src is not None:
            self.blocks[src].succs.append(Edge(dst, test, polarity))

    def temp(self, node: ast.AST) -> ast.Name:
        self._temps += 1
        return ast.Name(id=f"$t{self._temps}", ctx=ast.Load(), lineno=getattr(node, "lineno", 1),
                        col_offset=getattr(node, "col_offset", 0))

    # -- entry ------------------------------------------------------------------------
    def build(self, body: list[ast.stmt]) -> CFG:
        entry = self.new()
        self.exit = self.new()
        end = self.body(body, entry)
        self.link(end, self.exit)
        return CFG(entry, self.exit, self.blocks, frozenset(self.heads))

    def body(self, stmts: list[ast.stmt], cur: int | None) -> int | None:
        for stmt in stmts:
            if cur is None:
                return None  # the rest is unreachable
            if self.handlers and self.blocks[cur].ops:
                nxt = self.new()
                self.link(cur, nxt)
                cur = nxt
            cur = self.stmt(stmt, cur)
        return cur

    def branch(self, test: ast.expr, cur: int, on_true: int, on_false: int) -> None:
        """Edges for ``if test`` with short-circuit lowering of and/or/not."""
        if isinstance(test, ast.UnaryOp) and isinstance(test.op, ast.Not):
            self.branch(test.operand, cur, on_false, on_true)
        elif isinstance(test, ast.BoolOp):
            *first, last = test.values
            for value in first:
                nxt = self.new()
                if isinstance(test.op, ast.And):
                    self.branch(value, cur, nxt, on_false)
                else:
                    self.branch(value, cur, on_true, nxt)
                cur = nxt
            self.branch(last, cur, on_true, on_false)
        else:
            self.blocks[cur].ops.append(Eval(test))
            self.link(cur, on_true, test, True)
            self.link(cur, on_false, test, False)

    # -- statements -------------------------------------------------------------------
    def stmt(self, s: ast.stmt, cur: int) -> int | None:
        method = getattr(self, "s_" + type(s).__name__, None)
        if method is None:
            self.blocks[cur].ops.append(s)
            return cur
        return method(s, cur)

    def s_Return(self, s: ast.Return, cur: int) -> None:
        self.blocks[cur].ops.append(Return(s.value))
        self.link(cur, self.exit)
        return None

    def s_Raise(self, s: ast.Raise, cur: int) -> None:
        if s.exc is not None:
            self.blocks[cur].ops.append(Eval(s.exc))
        return None

    def s_Assert(self, s: ast.Assert, cur: int) -> int:
        self.blocks[cur].ops.append(Eval(s.test))
        return cur

    def s_Break(self, s: ast.Break, cur: int) -> None:
        if self.loops:
            self.link(cur, self.loops[-1][1])
        return None

    def s_Continue(self, s: ast.Continue, cur: int) -> None:
        if self.loops:
            self.link(cur, self.loops[-1][0])
        return None

    def s_If(self, s: ast.If, cur: int) -> int | None:
        then, other, after = self.new(), self.new(), self.new()
        self.branch(s.test, cur, then, other)
        self.link(self.body(s.body, then), after)
        self.link(self.body(s.orelse, other), after)
        return after

    def s_While(self, s: ast.While, cur: int) -> int | None:
        head, body, other, after = self.new(), self.new(), self.new(), self.new()
        self.heads.add(head)
        self.link(cur, head)
        self.branch(s.test, head, body, other)
        self.loops.append((head, after))
        self.link(self.body(s.body, body), head)
        self.loops.pop()
        self.link(self.body(s.orelse, other), after)
        return after

    def s_For(self, s: ast.For | ast.AsyncFor, cur: int) -> int | None:
        iterator = self.temp(s)
        self.blocks[cur].ops.append(ast.Assign(targets=[ast.Name(id=iterator.id, ctx=ast.Store())],
                                               value=s.iter, lineno=s.lineno,
                                               col_offset=s.col_offset))
        head, body, other, after = self.new(), self.new(), self.new(), self.new()
        self.heads.add(head)
        self.link(cur, head)
        self.link(head, body)
        self.link(head, other)
        self.blocks[body].ops.append(Bind(s.target, iterator, "iter"))
        self.loops.append((head, after))
        self.link(self.body(s.body, body), head)
        self.loops.pop()
        self.link(self.body(s.orelse, other), after)
        return after

    s_AsyncFor = s_For

    def s_With(self, s: ast.With | ast.AsyncWith, cur: int) -> int | None:
        for item in s.items:
            if item.optional_vars is not None:
                self.blocks[cur].ops.append(Bind(item.optional_vars, item.context_expr, "enter"))
            else:
                self.blocks[cur].ops.append(Eval(item.context_expr))
        return self.body(s.body, cur)

    s_AsyncWith = s_With

    def s_Try(self, s: ast.Try, cur: int) -> int | None:
        entries = tuple(self.new() for _ in s.handlers)
        after = self.new()
        self.handlers.append(entries)
        outer = self.catching
        self.catching = tuple(s.handlers) + outer
        start = self.new()
        self.link(cur, start)
        end = self.body(s.body, start)
        self.handlers.pop()
        self.catching = outer
        end = self.body(s.orelse, end)
        ends = [end]
        for entry, handler in zip(entries, s.handlers):
            if handler.name:
                target = ast.Name(id=handler.name, ctx=ast.Store())
                self.blocks[entry].ops.append(Bind(target, handler.type, "except"))
            ends.append(self.body(handler.body, entry))
        for end in ends:
            self.link(end, after)
        if s.finalbody:
            return self.body(s.finalbody, after)
        return after

    s_TryStar = s_Try

    def s_Match(self, s: ast.Match, cur: int) -> int | None:
        subject = self.temp(s)
        self.blocks[cur].ops.append(ast.Assign(targets=[ast.Name(id=subject.id, ctx=ast.Store())],
                                               value=s.subject, lineno=s.lineno,
                                               col_offset=s.col_offset))
        after = self.new()
        for case in s.cases:
            body, nxt = self.new(), self.new()
            self.link(cur, body)
            self.link(cur, nxt)
            self.blocks[body].ops.append(Bind(case.pattern, subject, "match"))
            if case.guard is not None:
                guarded = self.new()
                self.branch(case.guard, body, guarded, nxt)
                body = guarded
            self.link(self.body(case.body, body), after)
            cur = nxt
        self.link(cur, after)
        return after


def build_cfg(body: list[ast.stmt]) -> CFG:
    """The CFG of a statement list (a function, module or class body)."""
    return _Builder().build(body)
