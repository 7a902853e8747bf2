"""Members of ``enum.Enum`` classes defined in the workspace.

Python's ``EnumMeta`` turns each plain name the class body assigns (``NAVIGATION =
"navigation"``) into a *member*: an instance of the class whose ``value`` is what was
assigned and whose ``name`` is the name, with the class's methods bound to it. Read as a
plain class attribute, ``Mode.NAVIGATION.value`` and ``Mode.NAVIGATION.service_name()`` would
be attribute reads and method calls on a string (unknown), and topic tables kept in an enum
(``Topics.CMD_VEL.value``) would name nothing.

Enums mixed with ``str`` or ``int`` (``class Topic(str, Enum)``, ``StrEnum``, ``IntEnum``) are
left to the plain class-attribute reading: their members *are* strings and numbers wherever
a library takes them, which the assigned value already is.

This module only reads the syntax (which names are members); the interpreter makes the
member objects (``ObjectSemantics``).
"""
from __future__ import annotations

import ast

from .program import Class

#: Library classes whose subclasses have members (``enum``'s, by qualified name).
ENUM_BASES = frozenset({"enum.Enum", "enum.Flag"})
#: Bases that make the members plain strings or numbers to the code that takes them.
MIXIN_BASES = frozenset({"builtins.str", "builtins.int", "builtins.float", "builtins.bytes",
                         "enum.IntEnum", "enum.StrEnum", "enum.IntFlag", "enum.ReprEnum"})


def member_names(klass: Class) -> tuple[str, ...]:
    """The names ``klass``'s body makes members, in its order: plain assignments to names
    that are neither private nor special (``_ignore_``, ``__doc__``), of values that are not
    functions."""
    out: dict[str, None] = {}
    for stmt in klass.node.body:
        if isinstance(stmt, ast.Assign):
            targets = stmt.targets
            value = stmt.value
        elif isinstance(stmt, ast.AnnAssign) and stmt.value is not None:
            targets, value = [stmt.target], stmt.value
        else:
            continue
        if isinstance(value, ast.Lambda):
            continue
        out.update((t.id, None) for t in targets
                   if isinstance(t, ast.Name) and not t.id.startswith("_"))
    return tuple(out)


#: The prefix of a member's allocation site (no allocation site of a call starts with it).
_MEMBER_SITE = "enum:"


def member_site(klass: Class, name: str) -> str:
    """The allocation site of member ``name``: one object per member, whoever reads it."""
    return f"{_MEMBER_SITE}{klass.module.path}:{klass.qualname}.{name}"


def is_member_site(site: str) -> bool:
    """Whether an object allocated at ``site`` is an enum member: members are equal only to
    themselves (``Enum.__eq__`` is identity), so ``mode == Mode.SIM`` decides a branch."""
    return site.startswith(_MEMBER_SITE)
