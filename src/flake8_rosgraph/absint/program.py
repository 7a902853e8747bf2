"""The static shape of the analysed program: modules, functions, classes and scopes.

Built once from the parsed modules, before any abstract interpretation: it numbers
every function (incl. lambdas) and class, records who encloses whom, which names
each scope binds (Python's scoping rules: assignment makes a name local unless
declared ``global``/``nonlocal``), and resolves module names of imports, relative
ones included.  The engine only ever looks things up here.
"""
from __future__ import annotations

import ast
import functools
from dataclasses import dataclass, field
from typing import Callable

from .cfg import CFG, build_cfg
from .main_guard import script_steps
from .outline import ImportStatement


@dataclass
class Module:
    name: str            # dotted module name ("pkg.sub.mod")
    path: str            # root-relative POSIX path
    #: The parsed source, or ``None`` until :attr:`tree` is first read (see :attr:`source`).
    parsed: ast.Module | None
    #: The non-ASCII source lines by number: the only ones where ast's UTF-8 byte columns
    #: differ from character columns (all lines would cost memory for nothing).
    wide_lines: dict[int, str]
    is_package: bool = False
    #: Run as a program (a ``#!`` line naming Python): its folder is first on ``sys.path``.
    program: bool = False
    cfg: CFG | None = None
    globals: frozenset[str] = frozenset()
    #: A hash of the source bytes: what a cache of results computed from this module keys on.
    digest: str = ""
    #: Its import statements, known without the tree (:func:`.outline.import_statements`).
    imports: tuple[ImportStatement, ...] = ()
    #: The names its top level binds when it only declares (:func:`.outline.declared_names`).
    declares: tuple[str, ...] | None = None
    #: The attribute names it assigns (:func:`.outline.attribute_stores`).
    attribute_stores: frozenset[str] = frozenset()
    #: Whether it adds folders to ``sys.path`` (:func:`.outline.edits_sys_path`).
    edits_sys_path: bool = False
    #: Its number of lines, known without the tree: what analysing it costs, roughly.
    lines: int = 0
    #: Reads and parses the file, for a module made without its tree (its group's facts were
    #: expected from the cache): the tree and the wide lines.
    source: Callable[[], tuple[ast.Module, dict[int, str]]] | None = None

    @property
    def tree(self) -> ast.Module:
        return self._load()

    def _load(self) -> ast.Module:
        if self.parsed is None:
            self.parsed, self.wide_lines = self.source() if self.source is not None \
                else (ast.Module(body=[], type_ignores=[]), {})
        return self.parsed

    def column(self, node: ast.AST) -> int:
        """1-based character column of ``node`` (ast's ``col_offset`` counts UTF-8 bytes)."""
        line, col = getattr(node, "lineno", 1), getattr(node, "col_offset", 0)
        self._load()  # the wide lines come with the tree
        text = self.wide_lines.get(line)
        if text is not None:
            col = len(text.encode("utf-8")[:col].decode("utf-8", "replace"))
        return col + 1

    @functools.cached_property
    def script_steps(self) -> tuple[tuple[int, int], ...]:
        """Lines of the statements its run as a program always runs in order
        (:func:`.main_guard.script_steps`)."""
        return script_steps(self.tree)


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
    #: Decorated with ``contextlib.contextmanager`` (or its async twin): a call makes a
    #: context manager whose ``__enter__`` hands out what the generator yields.
    context_manager: bool = False
    #: Decorated with ``@<name>.setter``: Python calls it for ``obj.<name> = value`` (the
    #: property of that name), and reading ``obj.<name>`` never gives it.
    setter: bool = False
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


def _decorator_kind(node: ast.FunctionDef | ast.AsyncFunctionDef) -> str:
    for dec in node.decorator_list:
        name = dec.id if isinstance(dec, ast.Name) else getattr(dec, "attr", None)
        if name in ("staticmethod", "classmethod", "property"):
            return name
        if name == "cached_property":  # functools': read like a property, computed once
            return "property"
    return "function"


#: Decorators that turn a generator function into a context-manager factory (contextlib).
_CONTEXT_MANAGER_DECORATORS = frozenset({"contextmanager", "asynccontextmanager"})


def _is_context_manager(node: ast.FunctionDef | ast.AsyncFunctionDef) -> bool:
    """Read from the decorator's name, as the other decorator kinds are: the analysis binds
    the name to the function itself, not to what the decorator returns."""
    return any((dec.id if isinstance(dec, ast.Name) else getattr(dec, "attr", None))
               in _CONTEXT_MANAGER_DECORATORS for dec in node.decorator_list)


@dataclass
class _Scope:
    """Names one scope binds, reads and declares, gathered in the single walk."""

    fid: int | None = None
    bound: set[str] = field(default_factory=set)
    read: set[str] = field(default_factory=set)
    glob: set[str] = field(default_factory=set)
    nonloc: set[str] = field(default_factory=set)
    generator: bool = False


_COMPREHENSIONS = (ast.ListComp, ast.SetComp, ast.DictComp, ast.GeneratorExp)
_FUNCTION_NODES = frozenset((ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda))
#: Node kinds besides names and attributes that bind or declare something in their scope.
_BINDING_NODES = frozenset((ast.alias, ast.Global, ast.Nonlocal, ast.ExceptHandler, ast.MatchAs,
                            ast.MatchStar, ast.MatchMapping, ast.Yield, ast.YieldFrom,
                            ast.NamedExpr))
#: Node kinds that bind, read and define nothing: not worth a visit.
_NOTHING_INSIDE = (ast.expr_context, ast.operator, ast.boolop, ast.unaryop, ast.cmpop,
                   ast.Constant, ast.Pass, ast.Break, ast.Continue)


class Program:
    """Tables of modules, functions and classes, indexed by AST node for the engine."""

    def __init__(self, modules: list[Module]) -> None:
        self.modules: dict[str, Module] = {}
        for mod in sorted(modules, key=lambda m: m.path):
            self.modules.setdefault(mod.name, mod)
        self.imports: dict[str, frozenset[str]] = {}  # module -> absolute names it imports
        self._fresh_tables()
        #: (folder, name) -> the module importable as ``name`` from a file in ``folder`` when
        #: that folder is on ``sys.path`` (``name.py`` or ``name/__init__.py`` in it).
        self._in_folder: dict[tuple[str, str], str] = {}
        #: First components of the workspace's module names.
        self._tops: set[str] = set()
        #: File (or package folder) name -> the modules of that name, in path order.
        self._by_file_name: dict[str, list[str]] = {}
        #: Package name -> its folder (``pkg`` -> ``src/pkg``), for namespace folders inside it.
        self._package_folder: dict[str, str] = {}
        for mod in self.modules.values():
            folder, _, file = mod.path.rpartition("/")
            if mod.is_package:
                self._package_folder.setdefault(mod.name, folder)
                folder, _, file = folder.rpartition("/")
            elif file.endswith(".py"):
                file = file[:-3]
            else:
                file = ""  # an executable without the suffix: nothing can import it
            if file.isidentifier():
                self._in_folder.setdefault((folder, file), mod.name)
                names = self._by_file_name.setdefault(file, [])
                if mod.name not in names:
                    names.append(mod.name)
            if not mod.name.startswith("<"):
                self._tops.add(mod.name.partition(".")[0])
        for mod in self.modules.values():
            self.imports[mod.name] = self._absolute_imports(mod)

    def _absolute_imports(self, mod: Module) -> frozenset[str]:
        """Absolute names a module imports (its :attr:`Module.imports` resolved from where it is)."""
        out: set[str] = set()
        for statement in mod.imports:
            if statement[0] == "import":
                out.add(self.absolute_import(mod, statement[1]))
            else:
                _, name, level, names = statement
                base = self.resolve_import(mod, name, level)
                out.add(base)
                out.update(f"{base}.{alias}" for alias in names)
        return frozenset(out)

    def components(self) -> list[tuple[str, ...]]:
        """The workspace's modules in groups analysed apart, each sorted, in sorted order.

        Two modules are in one group when one imports the other, or a package the other's import
        runs (``import a.b.c`` runs ``a`` and ``a.b``), or a test file the ``conftest.py`` whose
        fixtures pytest hands it (:mod:`.fixtures`), directly or through others. The analysis
        of a group reads nothing of another: no global, class, function or object crosses
        between them, so each can be analysed — and its results kept — on its own.

        A declarative module (:meth:`shared_modules`) joins nobody: every group that imports
        it holds a copy, so a package's ``__init__.py``, a module of topic-name constants or a
        message package's re-exports do not weld all their importers into one group that any
        edit re-analyses whole. Its own analysis is the same in every copy, and without code the
        only facts it can give are diagnostics, which the graph keeps once.
        """
        from .fixtures import conftests_seen_from, is_test_file
        shared = self.shared_modules()
        leader = {name: name for name in self.modules}

        def find(name: str) -> str:
            while leader[name] != name:
                leader[name] = leader[leader[name]]  # halve the path on the way up
                name = leader[name]
            return name

        for name in self.modules:
            for other in self._imported_modules(name):
                if (other in shared) == (name in shared):
                    leader[find(other)] = find(name)
        by_path = {module.path: name for name, module in self.modules.items()}
        for name, module in self.modules.items():
            if is_test_file(module.path):
                for conftest in conftests_seen_from(module.path, by_path.get):
                    leader[find(conftest)] = find(name)
        groups: dict[str, set[str]] = {}
        for name in self.modules:
            groups.setdefault(find(name), set()).add(name)
        for members in groups.values():
            todo = [other for name in members for other in self._imported_modules(name) if other in shared]
            while todo:
                other = todo.pop()
                if other not in members:
                    members.add(other)
                    todo.extend(self._imported_modules(other))
        copied = set().union(*(members for members in groups.values() if not members <= shared))
        # A group of declarative modules only, each copied into a group that imports it, adds nothing.
        return sorted(tuple(sorted(group)) for group in groups.values()
                      if not group <= shared or not group <= copied)

    def _imported_modules(self, name: str) -> frozenset[str]:
        """The workspace modules ``name``'s imports run: those named, and the packages above them
        (worked out once: the grouping asks again for every module)."""
        found = self._imported.get(name)
        if found is None:
            out = set()
            for dotted in self.imports[name]:
                parts = dotted.split(".")
                for end in range(1, len(parts) + 1):
                    other = ".".join(parts[:end])
                    if other in self.modules:
                        out.add(other)
            out.discard(name)
            found = self._imported[name] = frozenset(out)
        return found

    def shared_modules(self) -> set[str]:
        """Modules each importing group analyses its own copy of (:meth:`components`).

        A module qualifies when it only declares (:func:`.outline.declared_names`), is not run
        as a program, imports only modules that qualify, and no module assigns one of its names
        as an attribute (``config.DEBUG = True`` changes what every importer reads, so they
        stay one group).
        """
        stored = set().union(*(m.attribute_stores for m in self.modules.values()))
        shared = {name for name, m in self.modules.items()
                  if m.declares is not None and not m.program and stored.isdisjoint(m.declares)}
        changed = True
        while changed:
            lost = {name for name in shared if not self._imported_modules(name) <= shared}
            shared -= lost
            changed = bool(lost)
        return shared

    def part(self, names: tuple[str, ...]) -> Program:
        """A program of the modules ``names`` only (a group of :meth:`components`), resolving
        imports as this one does: its functions and classes are numbered afresh, so what is
        analysed from it depends on those modules alone."""
        part = Program.__new__(Program)
        part.modules = {name: self.modules[name] for name in names}
        part.imports = {name: self.imports[name] for name in names}
        part._in_folder, part._tops, part._package_folder = self._in_folder, self._tops, self._package_folder
        part._by_file_name = self._by_file_name
        part._fresh_tables()
        return part

    def _fresh_tables(self) -> None:
        """The tables filled as modules are walked (:meth:`ensure`), empty."""
        self.functions: list[Function] = []
        self.classes: list[Class] = []
        self.fid_of: dict[int, int] = {}     # id(ast node) -> fid
        self.cid_of: dict[int, int] = {}     # id(ast node) -> cid
        #: Attribute names some workspace code assigns (``x.name = …``): any other attribute
        #: of an object with library bases can only come from the library.
        self.stored_attrs: set[str] = set()
        #: Names and attribute names some workspace code reads (``run``, ``helpers.run``):
        #: a module function named so may be called by code that is analysed later.
        self.read_names: set[str] = set()
        self.rejected: list[tuple[Module, str]] = []
        self._collected: set[str] = set()
        self._star_memo: dict[str, frozenset[str]] = {}
        self._library_star_memo: dict[str, tuple[str, ...]] = {}
        self._imported: dict[str, frozenset[str]] = {}  # see ``_imported_modules``

    def walked(self) -> list[Module]:
        """The modules walked so far (:meth:`ensure`), in name order: the ones the analysis used."""
        return [self.modules[name] for name in sorted(self._collected) if name in self.modules]

    def ensure(self, name: str) -> Module | None:
        """The module, its functions and classes numbered and its scopes gathered (done on
        first use: modules the analysis never needs are never walked). ``None`` if the
        module is unknown or nested too deeply to walk."""
        mod = self.modules.get(name)
        if mod is None or name in self._collected:
            return mod
        self._collected.add(name)
        try:
            self._collect(mod)
        except RecursionError:
            mod.globals = frozenset()
            self.rejected.append((mod, "nested too deeply to analyse"))
            return None
        return mod

    # -- building ---------------------------------------------------------------------
    def _collect(self, mod: Module) -> None:
        """One iterative walk over a module: number functions/classes, gather scopes."""
        top = _Scope()
        scopes: list[_Scope] = []
        # (node, scope, qualname prefix, enclosing fid, class cid the node is directly in)
        stack: list[tuple[ast.AST, _Scope, str, int | None, int | None]] = [
            (child, top, "", None, None) for child in reversed(mod.tree.body)]
        while stack:
            node, scope, prefix, fid, cid = stack.pop()
            todo: list[tuple] = []
            kind = type(node)  # ast.parse makes no subclasses of its node types: tests by identity
            if kind in _FUNCTION_NODES:
                lam = kind is ast.Lambda
                name = "<lambda>" if lam else node.name
                if not lam:
                    scope.bound.add(name)
                    todo += [(d, scope, prefix, fid, cid) for d in node.decorator_list]
                todo += [(d, scope, prefix, fid, cid) for d in node.args.defaults]
                todo += [(d, scope, prefix, fid, cid) for d in node.args.kw_defaults if d]
                func = Function(len(self.functions), node, mod, prefix + name, fid,
                                cid, frozenset(), frozenset(), frozenset(), frozenset())
                if not lam:
                    func.kind = _decorator_kind(node)
                    func.context_manager = _is_context_manager(node)
                    func.setter = any(isinstance(d, ast.Attribute) and d.attr == "setter"
                                      for d in node.decorator_list)
                    if cid is not None:
                        self.classes[cid].methods.setdefault(name, func.fid)
                self.functions.append(func)
                self.fid_of[id(node)] = func.fid
                inner = _Scope(func.fid)
                scopes.append(inner)
                a = node.args
                inner.bound.update(x.arg for x in a.posonlyargs + a.args + a.kwonlyargs)
                inner.bound.update(x.arg for x in (a.vararg, a.kwarg) if x)
                body = [node.body] if lam else node.body
                todo += [(b, inner, func.qualname + ".", func.fid, None) for b in body]
            elif kind is ast.ClassDef:
                scope.bound.add(node.name)
                todo += [(d, scope, prefix, fid, cid)
                         for d in node.decorator_list + node.bases + [k.value for k in node.keywords]]
                klass = Class(len(self.classes), node, mod, prefix + node.name, fid)
                self.classes.append(klass)
                self.cid_of[id(node)] = klass.cid
                body_scope = _Scope(None)  # class bodies bind class attributes, not locals
                body_scope.read = scope.read
                todo += [(b, body_scope, klass.qualname + ".", fid, klass.cid) for b in node.body]
            elif kind in _COMPREHENSIONS:
                # The first iterable runs in the enclosing scope; targets stay in the
                # comprehension (the interpreter evaluates it inline); reads count outside.
                comp = _Scope(None)
                comp.read = scope.read
                todo.append((node.generators[0].iter, scope, prefix, fid, cid))
                for i, gen in enumerate(node.generators):
                    todo.append((gen.target, comp, prefix, fid, cid))
                    if i:
                        todo.append((gen.iter, comp, prefix, fid, cid))
                    todo += [(c, comp, prefix, fid, cid) for c in gen.ifs]
                elts = [node.key, node.value] if isinstance(node, ast.DictComp) else [node.elt]
                todo += [(e, comp, prefix, fid, cid) for e in elts]
            else:
                if kind is ast.Name:
                    (scope.read if isinstance(node.ctx, ast.Load) else scope.bound).add(node.id)
                    if isinstance(node.ctx, ast.Load):
                        self.read_names.add(node.id)
                elif kind is ast.Attribute:
                    (self.read_names if isinstance(node.ctx, ast.Load) else self.stored_attrs).add(node.attr)
                elif kind not in _BINDING_NODES:
                    pass
                elif kind is ast.alias:
                    if node.name != "*":
                        scope.bound.add((node.asname or node.name).split(".")[0])
                elif isinstance(node, ast.Global):
                    scope.glob.update(node.names)
                elif isinstance(node, ast.Nonlocal):
                    scope.nonloc.update(node.names)
                elif isinstance(node, ast.ExceptHandler) and node.name:
                    scope.bound.add(node.name)
                elif isinstance(node, (ast.MatchAs, ast.MatchStar)) and node.name:
                    scope.bound.add(node.name)
                elif isinstance(node, ast.MatchMapping) and node.rest:
                    scope.bound.add(node.rest)
                elif isinstance(node, (ast.Yield, ast.YieldFrom)):
                    scope.generator = True
                elif isinstance(node, ast.NamedExpr) and isinstance(node.target, ast.Name):
                    scope.bound.add(node.target.id)
                todo += [(c, scope, prefix, fid, cid) for c in _child_nodes(node)]
            stack.extend(reversed(todo))
        # A ``global x`` at module level declares nothing; a function's ``global x`` that
        # assigns ``x`` binds a module global (``global node`` then ``node = Node(...)`` in
        # ``main``, read by the module's callbacks).
        mod.globals = frozenset(top.bound.union(*(sc.glob & sc.bound for sc in scopes)))
        for sc in scopes:
            func = self.functions[sc.fid]
            func.locals = frozenset(sc.bound - sc.glob - sc.nonloc)
            func.global_decl = frozenset(sc.glob)
            func.nonlocal_decl = frozenset(sc.nonloc)
            func.is_generator = sc.generator
        for sc in scopes:
            self._mark_cells(sc)

    def _mark_cells(self, scope: _Scope) -> None:
        """Record, on each enclosing function, the locals this function reads freely."""
        func = self.functions[scope.fid]
        free = (scope.read - func.locals - func.global_decl) | func.nonlocal_decl
        parent = func.parent
        while free and parent is not None:
            outer = self.functions[parent]
            captured = free & outer.locals
            if captured:
                outer.cellvars = outer.cellvars | captured
            free -= captured
            parent = outer.parent

    # -- queries ----------------------------------------------------------------------
    def star_names(self, mod: Module) -> frozenset[str]:
        """Names ``mod`` may bind through ``from … import *`` at its top level (transitively,
        a superset: which ones it really binds is the analysis's business, ``__all__``
        included)."""
        known = self._star_memo.get(mod.name)
        if known is not None:
            return known
        self._star_memo[mod.name] = frozenset()  # a cycle of star imports adds nothing
        out: set[str] = set()
        for stmt in mod.tree.body:
            if isinstance(stmt, ast.ImportFrom) and any(a.name == "*" for a in stmt.names):
                source = self.ensure(self.resolve_import(mod, stmt.module, stmt.level))
                if source is not None:
                    out |= source.globals | self.star_names(source)
        self._star_memo[mod.name] = frozenset(out)
        return self._star_memo[mod.name]

    def library_star_sources(self, mod: Module) -> tuple[str, ...]:
        """The modules outside the workspace ``mod`` star-imports at its top level (also
        under a top-level ``if``/``try``), sorted: a name nothing else binds there can only
        come from one of them."""
        known = self._library_star_memo.get(mod.name)
        if known is None:
            found = set()
            todo = list(mod.tree.body)
            while todo:
                stmt = todo.pop()
                if isinstance(stmt, ast.ImportFrom) and any(a.name == "*" for a in stmt.names):
                    base = self.resolve_import(mod, stmt.module, stmt.level)
                    if base and self.ensure(base) is None:
                        found.add(base)
                elif isinstance(stmt, (ast.If, ast.Try)):
                    todo.extend(stmt.body + stmt.orelse + getattr(stmt, "finalbody", [])
                                + [s for h in getattr(stmt, "handlers", []) for s in h.body])
            known = self._library_star_memo[mod.name] = tuple(sorted(found))
        return known

    def resolve_import(self, mod: Module, name: str | None, level: int) -> str:
        """The absolute dotted name of ``from <level dots><name> import …`` inside ``mod``."""
        if level == 0:
            return self.absolute_import(mod, name) if name else ""
        parts = mod.name.split(".")
        if not mod.is_package:
            parts = parts[:-1]
        if level > 1:
            parts = parts[: len(parts) - (level - 1)]
        base = ".".join(parts)
        if name:
            return f"{base}.{name}" if base else name
        return base

    def absolute_import(self, mod: Module, name: str) -> str:
        """The module name ``import <name>`` reaches from ``mod`` (see :meth:`_from_sys_path`),
        or else the module in a folder without ``__init__.py`` inside a package: Python makes
        such a folder a namespace package under the package (``backend.ws.base_ws`` is
        ``backend/ws/base_ws.py`` beside ``backend/__init__.py``), which the workspace's
        module names (they stop at a folder without ``__init__.py``) do not spell."""
        found = self._from_sys_path(mod, name)
        if found in self.modules:
            return found
        return self._inside_package(name) or self._from_added_path(mod, name) or found

    def _from_added_path(self, mod: Module, name: str) -> str | None:
        """The module ``import <name>`` reaches from a module that puts a folder on
        ``sys.path`` itself (``sys.path.append(os.path.join(os.path.dirname(__file__),
        '../common/imp'))`` before ``import DR_init``): the one workspace module of that
        file name, when there is exactly one. The folder is computed at run time, often from
        where the file is installed, so it is not followed; without the edit, or with two
        candidates, the name stays unresolved (a library's)."""
        top, dot, rest = name.partition(".")
        candidates = self._by_file_name.get(top, ())
        if len(candidates) != 1 or not mod.edits_sys_path:
            return None
        found = candidates[0] + dot + rest
        return found if found in self.modules else None

    def _inside_package(self, name: str) -> str | None:
        parts = name.split(".")
        for cut in range(len(parts) - 2, 0, -1):
            folder = self._package_folder.get(".".join(parts[:cut]))
            if folder is not None:
                return self._in_folder.get(("/".join([folder, *parts[cut:-1]]), parts[-1]))
        return None

    def _from_sys_path(self, mod: Module, name: str) -> str:
        """The module name ``import <name>`` reaches from ``mod`` through ``sys.path``.

        A file run as a program has its own folder first on ``sys.path``: ``import helper``
        there reaches ``helper.py`` beside it (scripts installed together, a node importing
        its base class from the next file). Taken only when the workspace has no module of
        that name, when the importing file is a program (its ``#!`` line), or when the one
        beside it is a second module of that name (two packages' scripts with the same file
        name): otherwise (a package module beside a stray file) the name keeps its meaning."""
        top, dot, rest = name.partition(".")
        folder = mod.path.rpartition("/")[0]
        beside = self._in_folder.get((folder, top))
        if beside is None and rest and (top not in self._tops or mod.program):
            # ``courses.load_course``: a folder without ``__init__.py`` is a namespace package
            # where it sits, beside the program or beside a folder above the importing module
            # (``courses/load_course.py`` importing ``courses.along_road``: the program that
            # imported it has ``courses/`` beside it).
            *inner, last = name.split(".")
            while True:
                found = self._in_folder.get(("/".join(p for p in (folder, *inner) if p), last))
                if found is not None or not folder:
                    return found if found is not None else name
                folder = folder.rpartition("/")[0]
        if beside is None or beside == top:
            return name
        if top in self._tops and not beside.startswith("<") and (not mod.program or beside == mod.name):
            # A package module with a ``#!`` line importing its package by its own file name
            # (``axis_camera/axis_camera.py``: ``from axis_camera.axis_ptz import …``): it runs
            # through the package (an entry point imports it), where the name is the package.
            return name
        return beside + dot + rest

    def closure_owner(self, fid: int, name: str) -> int | None:
        """The enclosing function whose local ``name`` the function ``fid`` refers to."""
        parent = self.functions[fid].parent
        while parent is not None:
            outer = self.functions[parent]
            if name in outer.locals:
                return parent
            parent = outer.parent
        return None


def _child_nodes(node: ast.AST) -> list[ast.AST]:
    """``ast.iter_child_nodes(node)`` without the nodes that hold nothing to collect, in the
    same order; a plain loop over ``_fields``, as this walk visits every node of a module."""
    out: list[ast.AST] = []
    for name in node._fields:
        value = getattr(node, name, None)
        if isinstance(value, list):
            out += [item for item in value
                    if isinstance(item, ast.AST) and not isinstance(item, _NOTHING_INSIDE)]
        elif isinstance(value, ast.AST) and not isinstance(value, _NOTHING_INSIDE):
            out.append(value)
    return out
