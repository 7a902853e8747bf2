"""What a module's statements say before any analysis: what it imports, whether its top
level only declares, and which attribute names it assigns.

These are read once per file, when it is parsed, and kept with the file's outline in the
cache (:class:`.workspace.Outlines`), so that the modules can be put in groups analysed
apart (:meth:`.program.Program.components`) without parsing the files of groups whose
results are kept. Only statement lists are walked: imports and assignment targets are
statements, and walking every expression of every file up front cost a tenth of a cold run.
"""
from __future__ import annotations

import ast
from typing import Iterator

#: A module's import statements, as :func:`import_statements` lists them: ``("import", name)``
#: and ``("from", module or None, level, names)``.
ImportStatement = tuple

#: Statement fields that hold statement lists (``handlers`` and ``cases`` hold their holders).
_BODIES = ("body", "orelse", "finalbody", "handlers", "cases")


def _statements(tree: ast.Module) -> Iterator[ast.AST]:
    """Every statement of ``tree``, nested ones included (in function and class bodies too)."""
    stack: list[ast.AST] = list(tree.body)
    while stack:
        stmt = stack.pop()
        yield stmt
        for name in _BODIES:
            children = getattr(stmt, name, None)
            if isinstance(children, list):
                stack.extend(c for c in children
                             if isinstance(c, (ast.stmt, ast.excepthandler, ast.match_case)))


def import_statements(tree: ast.Module) -> tuple[ImportStatement, ...]:
    """The import statements of a module, anywhere in its statements, in the order found:
    ``("import", name)`` and ``("from", module, level, names)``."""
    out: list[ImportStatement] = []
    for stmt in _statements(tree):
        if isinstance(stmt, ast.Import):
            out.extend(("import", a.name) for a in stmt.names)
        elif isinstance(stmt, ast.ImportFrom):
            out.append(("from", stmt.module, stmt.level, tuple(a.name for a in stmt.names)))
    return tuple(out)


def declared_names(tree: ast.Module) -> tuple[str, ...] | None:
    """The names a *declarative* module binds, sorted; ``None`` for any other module.

    A declarative module's top level only imports, and binds names to literals (``__all__``,
    version strings): a package's empty ``__init__.py``, or one that re-exports generated
    message classes. Running it does nothing its importers could change, and it defines no
    code they could call, so every group of modules that imports it can analyse its own copy
    (:meth:`.program.Program.components`) — unless some module assigns one of these names as
    an attribute (:func:`attribute_stores`).
    """
    names: set[str] = set()
    for stmt in tree.body:
        if isinstance(stmt, ast.Import):
            names.update(a.asname or a.name.partition(".")[0] for a in stmt.names)
        elif isinstance(stmt, ast.ImportFrom):
            if any(a.name == "*" for a in stmt.names):
                return None  # binds names nobody here can list
            names.update(a.asname or a.name for a in stmt.names)
        elif isinstance(stmt, ast.Expr) and isinstance(stmt.value, ast.Constant):
            continue  # a docstring
        elif isinstance(stmt, (ast.Assign, ast.AnnAssign)) and _literal(stmt.value):
            targets = stmt.targets if isinstance(stmt, ast.Assign) else [stmt.target]
            if not all(isinstance(t, ast.Name) for t in targets):
                return None
            names.update(t.id for t in targets)  # type: ignore[attr-defined]
        else:
            return None
    return tuple(sorted(names))


def _literal(node: ast.expr | None) -> bool:
    if isinstance(node, ast.Constant):
        return True
    if isinstance(node, (ast.List, ast.Tuple, ast.Set)):
        return all(_literal(element) for element in node.elts)
    return False


def attribute_stores(tree: ast.Module, mentions_setattr: bool) -> frozenset[str]:
    """The attribute names the module assigns or deletes (``x.name = …``, ``x.name += …``,
    ``for x.name in …``, ``del x.name``), on any object, anywhere in its statements.

    ``setattr`` stores a name given as a string: in a module that mentions it
    (``mentions_setattr``, a test of its text), every identifier-like string constant counts.
    """
    out: set[str] = set()
    for stmt in _statements(tree):
        if isinstance(stmt, ast.Assign):
            targets: list[ast.expr] = list(stmt.targets)
        elif isinstance(stmt, (ast.AugAssign, ast.AnnAssign, ast.For, ast.AsyncFor)):
            targets = [stmt.target]
        elif isinstance(stmt, ast.Delete):
            targets = list(stmt.targets)
        elif isinstance(stmt, (ast.With, ast.AsyncWith)):
            targets = [item.optional_vars for item in stmt.items if item.optional_vars is not None]
        else:
            continue
        while targets:
            target = targets.pop()
            if isinstance(target, ast.Attribute):
                out.add(target.attr)
            elif isinstance(target, (ast.Tuple, ast.List)):
                targets.extend(target.elts)
            elif isinstance(target, ast.Starred):
                targets.append(target.value)
    if mentions_setattr:
        out.update(node.value for node in ast.walk(tree)
                   if isinstance(node, ast.Constant) and isinstance(node.value, str)
                   and node.value.isidentifier())
    return frozenset(out)


_PATH_EDITS = frozenset({"append", "insert", "extend"})


def edits_sys_path(tree: ast.Module, mentions_sys_path: bool) -> bool:
    """Whether the module adds folders to ``sys.path`` (``sys.path.append(…)``,
    ``sys.path.insert(0, …)``, ``sys.path += …``) anywhere; only a module whose text mentions
    ``sys.path`` (``mentions_sys_path``) is walked."""
    if not mentions_sys_path:
        return False
    for node in ast.walk(tree):
        target = node.func.value if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) \
            and node.func.attr in _PATH_EDITS else node.target if isinstance(node, ast.AugAssign) else None
        if isinstance(target, ast.Attribute) and target.attr == "path" \
                and isinstance(target.value, ast.Name) and target.value.id == "sys":
            return True
    return False
