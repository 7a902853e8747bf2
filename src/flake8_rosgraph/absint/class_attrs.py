"""The data attributes a workspace class names in its source: what ``setattr(obj, name, v)``
with a name the analysis does not know may overwrite.

A configuration object filled by name (``for key, value in params.items(): setattr(cfg, key,
value)`` over a table longer than a value holds, or over keys read from a file) keeps none of
its defaults for sure. Reading the class-level default as the attribute's only value would
decide ``if cfg.use_left_arm:`` from the default and drop the code under it; these names are
the attributes such a store is taken to reach.
"""
from __future__ import annotations

import ast

from .program import Class


def data_attribute_names(klass: Class) -> frozenset[str]:
    """The names ``klass``'s body binds to data (``x = …``, ``x: int = …``, not methods or
    nested classes) and the attributes its methods store on their first parameter
    (``self.x = …``)."""
    out: set[str] = set()
    for stmt in klass.node.body:
        if isinstance(stmt, ast.Assign):
            out.update(t.id for t in stmt.targets if isinstance(t, ast.Name))
        elif isinstance(stmt, (ast.AnnAssign, ast.AugAssign)) and isinstance(stmt.target, ast.Name):
            out.add(stmt.target.id)
        elif isinstance(stmt, (ast.FunctionDef, ast.AsyncFunctionDef)) and stmt.args.args:
            out.update(_stored_on(stmt, stmt.args.args[0].arg))
    return frozenset(out)


def _stored_on(func: ast.FunctionDef | ast.AsyncFunctionDef, receiver: str) -> set[str]:
    """The attributes ``func`` assigns on its parameter ``receiver`` (``self.x = …``,
    ``self.x += …``, ``self.a, self.b = …``)."""
    return {node.attr for node in ast.walk(func)
            if isinstance(node, ast.Attribute) and isinstance(node.ctx, ast.Store)
            and isinstance(node.value, ast.Name) and node.value.id == receiver}
