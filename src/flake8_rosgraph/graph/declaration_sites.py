"""Parameter names written at declaration calls, read off the source: the names the code may
declare where the analysis does not follow it.

A node may hand itself to code the analysis cannot follow to the end — a builder chain whose
links return objects it loses, a framework's wrapper called on an unknown receiver — and
that code declares parameters on it (``self._cm.declare_parameter('can_bus', 'can1')``).
The graph then holds a node that seems not to declare ``can_bus``, and a launch file setting
it would look ineffective (ROS204). The name is written in the code, so it can be read off
it: a declaration call whose effect the analysis did not attribute to a known node leaves
that one name open, and nothing else (the unknown stays local to the name).

Only calls spelt ``declare_parameter('name', …)`` or ``declare_parameters('ns', [('name',
…), …])`` with the names written as string constants count; a computed name is the
analysis' business.
"""
from __future__ import annotations

import ast
from typing import Collection, Iterable, Iterator

from ..absint.program import Module


def _text(node: ast.expr | None) -> str | None:
    return node.value if isinstance(node, ast.Constant) and isinstance(node.value, str) else None


def _argument(call: ast.Call, index: int, keyword: str) -> ast.expr | None:
    for kw in call.keywords:
        if kw.arg == keyword:
            return kw.value
    return call.args[index] if index < len(call.args) else None


def _names(call: ast.Call, method: str) -> Iterator[str]:
    if method == "declare_parameter":
        name = _text(_argument(call, 0, "name"))
        if name:
            yield name
        return
    namespace = _text(_argument(call, 0, "namespace"))
    entries = _argument(call, 1, "parameters")
    if namespace is None or not isinstance(entries, (ast.List, ast.Tuple)):
        return
    for entry in entries.elts:
        name = _text(entry.elts[0]) if isinstance(entry, ast.Tuple) and entry.elts else None
        if name:
            yield f"{namespace}.{name}" if namespace else name


#: The methods that declare parameters.
DECLARING = ("declare_parameter", "declare_parameters")


def written_declarations(modules: Iterable[Module], read_names: Collection[str]
                         ) -> Iterator[tuple[str, int, str]]:
    """``(path, line, name)`` of every parameter name written at a declaration call of
    ``modules`` (those the analysis walked: the others cannot hold a node); ``read_names``:
    the attribute names they read (none of :data:`DECLARING`: nothing to look for)."""
    if not any(method in read_names for method in DECLARING):
        return
    for module in modules:
        for node in ast.walk(module.tree):
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) \
                    and node.func.attr in DECLARING:
                for name in _names(node, node.func.attr):
                    yield module.path, node.lineno, name
