"""``isinstance(x, T)`` decided where the values say it, so that a branch on a type test is
taken only by the values that pass it.

Functions taking ``Union[int, PoseStamped]`` and branching on ``isinstance`` are analysed
once per calling context; without deciding the test, every branch would see every value.
The test is decided only when every possibility of ``x`` answers the same for every class
of ``T``:

* a constant or a tuple/list/dict shape has an exact Python type, whose MRO holds only
  builtins (abstract base classes such as ``collections.abc.Sequence`` stay undecided);
* an instance of a library class ``C`` (made by calling ``C``) is an instance of ``C``, and is
  taken not to be a ``bool``/``int``/``float``/``complex``/``str``/``bytes``/``NoneType`` or a
  builtin container: library classes deriving from those are not constructed that way in
  the code this analyses (and a wrong guess only costs a branch, never a crash).

Anything else leaves the test undecided (both branches).
"""
from __future__ import annotations

import builtins
from typing import Callable

from .values import BOOLS, Atom, Coll, Const, DictAtom, Extern, Obj, Seq, Value, const, soften

_BUILTIN_TYPES: dict[str, type] = {
    name: getattr(builtins, name) for name in (
        "bool", "int", "float", "complex", "str", "bytes", "list", "tuple", "dict", "set",
        "frozenset", "object")}
#: Where abstract base classes live: a builtin value may be registered as their instance.
_ABSTRACT = ("collections.abc.", "numbers.", "typing.", "abc.", "os.PathLike")
_CONTAINER_TYPES = {"list": list, "tuple": tuple, "dict": dict, "set": set, "frozenset": frozenset}


#: The complete list of a library class's ancestors, when it is known (else ``None``).
Ancestors = Callable[[str], "list[str] | None"]


def isinstance_value(subject: Value, classes: Value, ancestors: Ancestors = lambda qualname: None) -> Value:
    """The abstract result of ``isinstance(subject, classes)``. An instance of a library class
    whose ``ancestors`` are known is no instance of any other class."""
    targets = _targets(classes)
    if targets is None or subject.is_top or subject.is_bottom:
        return BOOLS
    answers = set()
    for atom in subject:
        answer = _any_of(atom, targets, ancestors)
        if answer is None:
            return BOOLS
        answers.add(answer)
        if len(answers) > 1:
            return BOOLS
    decided = const(answers.pop())
    # An overridable default decides nothing about control flow (see ``truth``).
    return soften(decided) if subject.soft else decided


def _targets(classes: Value) -> list[str] | None:
    """The qualified names of the classes tested against, if every one is a library class."""
    if classes.is_top or len(classes.atoms) != 1:
        return None
    (atom,) = classes.atoms
    if isinstance(atom, Extern):
        return [atom.qualname]
    if isinstance(atom, Seq) and atom.kind == "tuple":
        out = []
        for item in atom.items:
            found = _targets(item)
            if found is None:
                return None
            out.extend(found)
        return out
    return None


def _any_of(atom: Atom, targets: list[str], ancestors: Ancestors) -> bool | None:
    answers = [_is_instance(atom, target, ancestors) for target in targets]
    if any(a is True for a in answers):
        return True
    return False if all(a is False for a in answers) else None


def _python_type(atom: Atom) -> type | None:
    if isinstance(atom, Const):
        return type(atom.value)
    if isinstance(atom, (Seq, Coll)):
        return _CONTAINER_TYPES.get(atom.kind)
    if isinstance(atom, DictAtom):
        return dict
    return None


def _is_instance(atom: Atom, target: str, ancestors: Ancestors) -> bool | None:
    builtin = target[len("builtins."):] if target.startswith("builtins.") else None
    exact = _python_type(atom)
    if exact is not None:
        if builtin in _BUILTIN_TYPES:
            return issubclass(exact, _BUILTIN_TYPES[builtin])
        if builtin is None and not target.startswith(_ABSTRACT):
            return False  # a builtin type's MRO holds builtins only
        return None
    if isinstance(atom, Obj) and isinstance(atom.cls, Extern):
        if atom.cls.qualname == target:
            return True
        if builtin in _BUILTIN_TYPES and builtin != "object" \
                and not atom.cls.qualname.startswith("builtins."):
            return False
        known = ancestors(atom.cls.qualname)
        if known is not None:
            return target in known or target == "builtins.object"
    return None
