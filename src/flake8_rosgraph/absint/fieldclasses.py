"""Classes whose ``__init__`` is written from their annotated fields, not by the workspace.

``@dataclass`` (and attrs' ``@define``/``@attr.s``), ``typing.NamedTuple`` and pydantic's
``BaseModel`` build ``__init__`` from the class body's annotated names, in order, base
classes' fields first: ``LidarConfig(topic='front_scan')`` sets ``topic`` on the instance,
and the class-level ``topic: str = 'scan'`` is only the default. Read as a plain class
attribute, that default would name the entity whatever the caller passed (a confident wrong
name). A class derived from a library class no stub models, called with keywords that name
its annotated fields, is read the same way (pydantic models behind a framework's base class:
a tool's ``connector: Connector`` given as ``Tool(connector=c)``).

This module only reads the syntax: which fields a class declares and whether Python or a
library writes its ``__init__`` from them; the interpreter binds the arguments
(``CallSemantics.construct``).
"""
from __future__ import annotations

import ast
from dataclasses import dataclass, field

from .program import Class

#: Decorators that write ``__init__`` from the fields (last dotted parts as written).
_DECORATORS = frozenset({"dataclass", "dataclasses.dataclass", "pydantic.dataclasses.dataclass",
                         "attr.s", "attr.attrs", "attr.define", "attr.frozen", "attr.mutable",
                         "attrs.define", "attrs.frozen", "attrs.mutable", "define", "frozen",
                         "mutable"})
#: Library classes whose subclasses get an ``__init__`` from their fields.
FIELD_BASES = frozenset({"typing.NamedTuple", "pydantic.BaseModel", "pydantic.main.BaseModel",
                         "pydantic_settings.BaseSettings"})
#: Annotations that declare no instance field.
_NOT_FIELDS = frozenset({"ClassVar", "typing.ClassVar", "InitVar", "dataclasses.InitVar"})


@dataclass(frozen=True)
class Field:
    name: str
    #: The class-level value is a ``field(...)``/``Field(...)`` call (its default is not the
    #: value itself), or there is none.
    computed_default: bool
    has_default: bool
    init: bool = True
    #: For a ``field(...)`` default: the expression of its ``default=``, or of the callable
    #: its ``default_factory=`` (attrs: ``factory=``) calls for each instance (``factory``).
    default_expr: ast.expr | None = field(default=None, compare=False)
    factory: bool = False


def _dotted(expr: ast.expr) -> str | None:
    if isinstance(expr, ast.Name):
        return expr.id
    if isinstance(expr, ast.Attribute):
        head = _dotted(expr.value)
        return f"{head}.{expr.attr}" if head else None
    return None


def decorated_fields(klass: Class) -> bool:
    """Whether a decorator of ``klass`` writes its ``__init__`` from its fields."""
    for dec in klass.node.decorator_list:
        name = _dotted(dec.func if isinstance(dec, ast.Call) else dec)
        if name in _DECORATORS:
            if isinstance(dec, ast.Call) and any(
                    kw.arg == "init" and isinstance(kw.value, ast.Constant) and kw.value.value is False
                    for kw in dec.keywords):
                return False
            return True
    return False


def own_fields(klass: Class) -> list[Field]:
    """The fields ``klass``'s own body declares, in order."""
    out: list[Field] = []
    for stmt in klass.node.body:
        if not isinstance(stmt, ast.AnnAssign) or not isinstance(stmt.target, ast.Name):
            continue
        annotation = stmt.annotation
        head = annotation.value if isinstance(annotation, ast.Subscript) else annotation
        if _dotted(head) in _NOT_FIELDS:
            continue
        value = stmt.value
        computed = isinstance(value, ast.Call) and (_dotted(value.func) or "").rpartition(".")[2] in (
            "field", "Field", "ib", "attrib")
        init = not (computed and any(kw.arg == "init" and isinstance(kw.value, ast.Constant)
                                     and kw.value.value is False for kw in value.keywords))
        given = {kw.arg: kw.value for kw in value.keywords} if computed else {}
        factory = given.get("default_factory", given.get("factory"))
        out.append(Field(stmt.target.id, computed, value is not None, init,
                         factory if factory is not None else given.get("default"), factory is not None))
    return out
