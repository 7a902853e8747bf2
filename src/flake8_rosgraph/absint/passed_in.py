"""Objects a function receives from no analysed caller, known only by their annotation.

A helper written for whoever calls it (``def wait_for(node: Node, name: str)``, a launch test's
``async def test_smoke(self, node: Node)`` run by a decorator the analysis does not apply)
is analysed as an entry with unknown arguments. Calls on an unknown receiver are not followed,
so the clients and publishers it creates on ``node`` were lost with no trace. When the
parameter's annotation names a library class whose model says objects of it are *passed in*
(``passed_in = true``: rclpy's ``Node``), the entry binds the parameter to one object of that
class standing for whatever the caller passes: its calls are followed, and the graph puts what
they create on a node of unknown name and namespace, located at the function
(:meth:`~flake8_rosgraph.graph.builder.GraphBuilder`). Only library classes qualify: a
workspace class's fields, never set on such an object, would read as nothing (⊥) and cut the
function short.
"""
from __future__ import annotations

import ast

from .program import Function

_PREFIX = "passed:"


def passed_in_site(fid: int, name: str) -> str:
    """The allocation site of the object parameter ``name`` of function ``fid`` stands for."""
    return f"{_PREFIX}{fid}:{name}"


def passed_in_parameter(site: str) -> tuple[int, str] | None:
    """``(fid, parameter name)`` of a site made by :func:`passed_in_site`, else ``None``."""
    if not site.startswith(_PREFIX):
        return None
    fid, _, name = site[len(_PREFIX):].partition(":")
    return (int(fid), name) if fid.isdigit() and name else None


def annotation(func: Function, name: str) -> ast.expr | None:
    """The annotation of ``func``'s named (not ``*args``/``**kwargs``) parameter ``name``
    when it is a dotted name (``Node``, ``rclpy.node.Node``, also written as a string: a
    forward reference), the only form read."""
    a = func.node.args
    for param in a.posonlyargs + a.args + a.kwonlyargs:
        if param.arg == name:
            found = param.annotation
            if isinstance(found, ast.Constant) and isinstance(found.value, str):
                try:
                    found = ast.parse(found.value.strip(), mode="eval").body
                except (SyntaxError, ValueError, RecursionError):
                    return None
            expr = found
            while isinstance(expr, ast.Attribute):
                expr = expr.value
            return found if isinstance(expr, ast.Name) else None
    return None
