"""The static shape of the analysed program: modules, functions, classes and scopes.

Built once from the parsed modules, before any abstract interpretation: it numbers
every function (incl. lambdas) and class, records who encloses whom, which names
each scope binds (Python's scoping rules: assignment makes a name local unless
declared ``global``/``nonlocal``), and resolves module names of imports, relative
ones included.  The engine only ever looks things up here.
"""
from __future__ import annotations

import ast
from dataclasses import dataclass, field

from .cfg import CFG, build_cfg


@dataclass
class Module:
    name: str            # dotted module name ("pkg.sub.mod")
    path: str            # root-relative POSIX path
    tree: ast.Module
    lines: list[str]     # source lines, for byte → character column conversion
    is_package: bool = False
    cfg: CFG | None = None
    globals: frozenset[str] = frozenset()

    def column(self, node: ast.AST) -> int:
        """1-based character column of ``node`` (ast's ``col_offset`` counts UTF-8 bytes)."""
        line, col = getattr(node, "lineno", 1), getattr(node, "col_offset", 0)
        if 0 < line <= len(self.lines):
            text = self.lines[line - 1]
            if not text.isascii():
                col = len(text.encode("utf-8")[:col].decode("utf-8", "replace"))
        return col + 1


@dataclass
class Function:
    fid: int
    node: ast.FunctionDef | ast.AsyncFunctionDef | ast.Lambda
    module: Module
    qualname: str                  # __qualname__ without "<locals>."
    parent: int | None             # enclosing function fid
    cls: int | None                # class this is a method of (defined directly in its body)
    locals: frozenset[str]
    cellvars: frozenset[str]       # locals read by nested functions
    global_decl: frozenset[str]
    nonlocal_decl: frozenset[str]
    kind: str = "function"         # "function" | "staticmethod" | "classmethod" | "property"
    is_generator: bool = False
    _cfg: CFG | None = None

    @property
    def cfg(self) -> CFG:
        if self._cfg is None:
            body = self.node.body
            if isinstance(body, ast.expr):  # lambda
                body = [ast.Return(value=body, lineno=body.lineno, col_offset=body.col_offset)]
            self._cfg = build_cfg(body)
        return self._cfg


@dataclass
class Class:
    cid: int
    node: ast.ClassDef
    module: Module
    qualname: str
    parent: int | None             # enclosing function fid
    methods: dict[str, int] = field(default_factory=dict)
    _cfg: CFG | None = None

    @property
    def cfg(self) -> CFG:
        if self._cfg is None:
            self._cfg = build_cfg(self.node.body)
        return self._cfg


_SCOPES = (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda, ast.ClassDef,
           ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)


def _scope_children(node: ast.AST):
    """Direct children of a scope, not descending into nested scopes (but into their
    decorators, defaults and bases, which run in the enclosing scope)."""
    for child in ast.iter_child_nodes(node):
        if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef)):
            yield from child.decorator_list
            yield from child.args.defaults
            yield from (d for d in child.args.kw_defaults if d is not None)
            yield _Binder(child.name)
        elif isinstance(child, ast.ClassDef):
            yield from child.decorator_list
            yield from child.bases
            yield from (k.value for k in child.keywords)
            yield _Binder(child.name)
        elif isinstance(child, ast.Lambda):
            yield from child.args.defaults
        elif isinstance(child, (ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)):
            yield child.generators[0].iter
        else:
            yield child


@dataclass
class _Binder:
    name: str


def scope_names(node: ast.AST) -> tuple[set[str], set[str], set[str], set[str], bool]:
    """(bound, read, global-declared, nonlocal-declared, is_generator) of one scope."""
    bound: set[str] = set()
    read: set[str] = set()
    glob: set[str] = set()
    nonloc: set[str] = set()
    generator = False
    stack = list(_scope_children(node))
    while stack:
        cur = stack.pop()
        if isinstance(cur, _Binder):
            bound.add(cur.name)
            continue
        if isinstance(cur, ast.Name):
            (read if isinstance(cur.ctx, ast.Load) else bound).add(cur.id)
        elif isinstance(cur, ast.arg):
            bound.add(cur.arg)
        elif isinstance(cur, ast.alias):
            bound.add((cur.asname or cur.name).split(".")[0])
        elif isinstance(cur, ast.Global):
            glob.update(cur.names)
        elif isinstance(cur, ast.Nonlocal):
            nonloc.update(cur.names)
        elif isinstance(cur, ast.ExceptHandler) and cur.name:
            bound.add(cur.name)
        elif isinstance(cur, (ast.MatchAs, ast.MatchStar)) and cur.name:
            bound.add(cur.name)
        elif isinstance(cur, ast.MatchMapping) and cur.rest:
            bound.add(cur.rest)
        elif isinstance(cur, (ast.Yield, ast.YieldFrom)):
            generator = True
        elif isinstance(cur, ast.NamedExpr) and isinstance(cur.target, ast.Name):
            bound.add(cur.target.id)
        stack.extend(_scope_children(cur))
    return bound - glob - nonloc, read, glob, nonloc, generator


def _decorator_kind(node: ast.FunctionDef | ast.AsyncFunctionDef) -> str:
    for dec in node.decorator_list:
        name = dec.id if isinstance(dec, ast.Name) else getattr(dec, "attr", None)
        if name in ("staticmethod", "classmethod", "property"):
            return name
    return "function"


class Program:
    """Tables of modules, functions and classes, indexed by AST node for the engine."""

    def __init__(self, modules: list[Module]) -> None:
        self.modules: dict[str, Module] = {}
        for mod in sorted(modules, key=lambda m: m.path):
            self.modules.setdefault(mod.name, mod)
        self.functions: list[Function] = []
        self.classes: list[Class] = []
        self.fid_of: dict[int, int] = {}     # id(ast node) -> fid
        self.cid_of: dict[int, int] = {}     # id(ast node) -> cid
        self.rejected: list[tuple[Module, str]] = []
        for mod in list(self.modules.values()):
            bound, _, _, _, _ = scope_names(mod.tree)
            mod.globals = frozenset(bound)
            try:
                self._collect(mod.tree, mod, "", None, None)
            except RecursionError:
                # Nesting too deep for a recursive walk: leave the module out, say so.
                del self.modules[mod.name]
                self.rejected.append((mod, "nested too deeply to analyse"))

    # -- building ---------------------------------------------------------------------
    def _collect(self, node: ast.AST, mod: Module, prefix: str, fid: int | None,
                 cid: int | None) -> None:
        for child in ast.iter_child_nodes(node):
            if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)):
                name = "<lambda>" if isinstance(child, ast.Lambda) else child.name
                bound, read, glob, nonloc, gen = scope_names(child)
                func = Function(len(self.functions), child, mod, prefix + name, fid, cid,
                                frozenset(bound), frozenset(), frozenset(glob),
                                frozenset(nonloc), is_generator=gen)
                if not isinstance(child, ast.Lambda):
                    func.kind = _decorator_kind(child)
                self.functions.append(func)
                self.fid_of[id(child)] = func.fid
                if cid is not None and not isinstance(child, ast.Lambda):
                    self.classes[cid].methods.setdefault(child.name, func.fid)
                self._collect(child, mod, func.qualname + ".", func.fid, None)
            elif isinstance(child, ast.ClassDef):
                klass = Class(len(self.classes), child, mod, prefix + child.name, fid)
                self.classes.append(klass)
                self.cid_of[id(child)] = klass.cid
                self._collect(child, mod, klass.qualname + ".", fid, klass.cid)
            else:
                self._collect(child, mod, prefix, fid, cid)
        if fid is not None and node is self.functions[fid].node:
            self._mark_cells(fid)

    def _mark_cells(self, fid: int) -> None:
        """Record, on each enclosing function, the locals this function reads freely."""
        func = self.functions[fid]
        _, read, _, _, _ = scope_names(func.node)
        free = (read - func.locals - func.global_decl) | func.nonlocal_decl
        parent = func.parent
        while free and parent is not None:
            outer = self.functions[parent]
            captured = free & outer.locals
            if captured:
                outer.cellvars = outer.cellvars | captured
            free -= captured
            parent = outer.parent

    # -- queries ----------------------------------------------------------------------
    def resolve_import(self, mod: Module, name: str | None, level: int) -> str:
        """The absolute dotted name of ``from <level dots><name> import …`` inside ``mod``."""
        if level == 0:
            return name or ""
        parts = mod.name.split(".")
        if not mod.is_package:
            parts = parts[:-1]
        if level > 1:
            parts = parts[: len(parts) - (level - 1)]
        base = ".".join(parts)
        if name:
            return f"{base}.{name}" if base else name
        return base

    def closure_owner(self, fid: int, name: str) -> int | None:
        """The enclosing function whose local ``name`` the function ``fid`` refers to."""
        parent = self.functions[fid].parent
        while parent is not None:
            outer = self.functions[parent]
            if name in outer.locals:
                return parent
            parent = outer.parent
        return None
