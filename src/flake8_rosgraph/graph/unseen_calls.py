"""Names a node hands to code the analysis cannot see, together with the node itself.

A node class that passes ``self`` and a name to a library no stub models
(``hbba_lite.OnOffHbbaSubscriber(self, Image, 'image_raw', ...)``, a company's
publisher wrapper) has ends the graph does not hold: the library creates them on the
node. Those names are written in the code, so they can be read off it, though not
their kind (topic, service) nor role. The rules that judge what a node *lacks* — a
remap that matches nothing (ROS202), an end with no partner (ROS001, ROS003) — must
not take such a name for unused.

Only string constants written directly as arguments of such a call count: a name
the code computes stays an unknown (the analysis' business), and a call that does not
hand over the node cannot create ends on it.
"""
from __future__ import annotations

import ast
from typing import Callable, Iterator

#: The receiver a node class passes to hand itself over.
SELF = "self"
#: The receiver in a helper class the node was handed to (``MovementCommands(self, ...)``): it
#: holds the node in an attribute (``self.node``) or a parameter, which one is not followed.
HELD = "<held>"


def _imported(tree: ast.Module) -> dict[str, str]:
    """Local name -> the dotted name it is bound to by the module's absolute imports."""
    out: dict[str, str] = {}
    for stmt in tree.body:
        if isinstance(stmt, ast.Import):
            for alias in stmt.names:
                if alias.asname:
                    out[alias.asname] = alias.name
                else:
                    top = alias.name.split(".", 1)[0]
                    out[top] = top
        elif isinstance(stmt, ast.ImportFrom) and not stmt.level and stmt.module:
            for alias in stmt.names:
                if alias.name != "*":
                    out[alias.asname or alias.name] = f"{stmt.module}.{alias.name}"
    return out


def _dotted(func: ast.expr, imported: dict[str, str]) -> str | None:
    """``hbba_lite.OnOffHbbaPublisher`` for a callee written through an import, else ``None``."""
    parts: list[str] = []
    while isinstance(func, ast.Attribute):
        parts.append(func.attr)
        func = func.value
    if not isinstance(func, ast.Name) or func.id not in imported:
        return None
    return ".".join([imported[func.id], *reversed(parts)])


def _is_receiver(arg: ast.expr, receiver: str) -> bool:
    """``receiver`` itself, or (for :data:`HELD`) an attribute of ``self`` or a parameter."""
    if receiver == HELD:
        return isinstance(arg, ast.Attribute) and isinstance(arg.value, ast.Name) \
            and arg.value.id == SELF or isinstance(arg, ast.Name) and arg.id != SELF
    return isinstance(arg, ast.Name) and arg.id == receiver


def _hands_over(call: ast.Call, receiver: str) -> bool:
    return any(_is_receiver(arg, receiver) for arg in [*call.args, *(k.value for k in call.keywords)])


def _strings(call: ast.Call) -> Iterator[str]:
    for arg in [*call.args, *(k.value for k in call.keywords)]:
        if isinstance(arg, ast.Constant) and isinstance(arg.value, str) and arg.value:
            yield arg.value


def names_handed_to_unseen_code(body: ast.AST, tree: ast.Module, seen: Callable[[str], bool],
                                receiver: str = SELF) -> tuple[str, ...]:
    """The string arguments of calls in ``body`` (a node's class) that hand ``receiver`` to a
    callable imported into ``tree`` and not ``seen`` (neither workspace code nor a stub),
    sorted and without repeats."""
    imported = _imported(tree)
    found: set[str] = set()
    for call in ast.walk(body):
        if not isinstance(call, ast.Call) or not _hands_over(call, receiver):
            continue
        callee = _dotted(call.func, imported)
        if callee is not None and not seen(callee):
            found.update(_strings(call))
    return tuple(sorted(found))


def helpers_handed(body: ast.AST, receiver: str = SELF) -> tuple[str, ...]:
    """The last name of every callee in ``body`` that is handed ``receiver`` and is not an
    import (``MovementCommands`` in ``MovementCommands(self, 'head')``): candidates for a
    workspace helper class that may hand the node on to unseen code."""
    found: set[str] = set()
    for call in ast.walk(body):
        if isinstance(call, ast.Call) and _hands_over(call, receiver):
            func = call.func
            last = func.attr if isinstance(func, ast.Attribute) else func.id if isinstance(func, ast.Name) else None
            if last is not None and last[:1].isupper():
                found.add(last)
    return tuple(sorted(found))
