"""Containers filled in place: what ``lst.append(x)``, ``d[k] = v`` & co. make of the value.

Abstract values are immutable, so a mutation is followed by rebinding the variable or
attribute the container was reached through (the interpreter does that, as for records).
A known-length list that is mutated becomes a collection of unknown length holding the
old and new elements: its emptiness is then undecided, so code guarded by ``if not lst``
stays reachable both ways.  Only the holder named at the call is updated; another alias of
the same list (a helper it is passed to) keeps its old value, so an *empty* list or dict
is never trusted to stay empty; a non-empty one filled further through an alias loses
those additions (a documented limit).
"""
from __future__ import annotations

from typing import Callable

from .values import TOP, Coll, DictAtom, Seq, Value, atoms, join_all

#: Methods that change a list, set or dict in place.
MUTATORS = frozenset({"append", "extend", "insert", "add", "update", "setdefault", "clear",
                      "remove", "pop", "discard", "sort", "reverse"})
#: Pairs a dict keeps before it is given up as unknown (a dict filled in a loop).
MAX_DICT_ITEMS = 64


def may_be_filled_elsewhere(atom) -> bool:
    """An empty list or dict: code the analysis does not see rebinding (a helper it is passed
    to, another alias) may fill it, so iterating a value that is only ever empty yields
    unknown elements and its emptiness decides no branch — a loop over it must not be dead
    code. (Joined with filled versions of itself, the empty one is just its first state.)"""
    return (isinstance(atom, Seq) and atom.kind == "list" and not atom.items) or \
        (isinstance(atom, DictAtom) and not atom.items)


def mutated(value: Value, method: str, args: list[Value],
            elements: Callable[[Value], Value]) -> Value:
    """``value`` after ``value.method(*args)``; ``elements`` gives what iterating a value
    yields (for ``extend``/``update``)."""
    if value.is_top:
        return value
    out = []
    for atom in value:
        out.append(_mutated_atom(atom, method, args, elements))
    return atoms(out, value.soft) if all(a is not None for a in out) else TOP


def _mutated_atom(atom, method: str, args: list[Value], elements):
    if isinstance(atom, DictAtom):
        if method == "setdefault" and len(args) > 1:
            return _with_pair(atom, args[0], args[1])
        if method == "update" and args:
            added = list(args[0]) if not args[0].is_top else None
            if added is None or not all(isinstance(a, DictAtom) for a in added):
                return None
            result = atom
            for other in added:
                for key, item in other.items:
                    result = _with_pair(result, key, item)
                    if result is None:
                        return None
            return result
        return atom if method in ("pop", "clear") else None
    if isinstance(atom, (Seq, Coll)):
        kind = atom.kind if atom.kind != "tuple" else None
        if kind is None:
            return atom  # tuples have no mutators: the call fails at run time, value unchanged
        old = join_all(atom.items) if isinstance(atom, Seq) else atom.elem
        if method in ("append", "add") and args:
            return Coll(kind, old.join(args[0]))
        if method == "insert" and len(args) > 1:
            return Coll(kind, old.join(args[1]))
        if method in ("extend", "update") and args:
            return Coll(kind, old.join(elements(args[0])))
        return Coll(kind, old)
    return atom  # an object or library value: its own methods model it


def with_item(value: Value, key: Value, item: Value) -> Value:
    """``value`` after ``value[key] = item``."""
    if value.is_top:
        return value
    out = []
    for atom in value:
        if isinstance(atom, DictAtom):
            atom = _with_pair(atom, key, item)
        elif isinstance(atom, Seq) and atom.kind == "list" or isinstance(atom, Coll):
            old = join_all(atom.items) if isinstance(atom, Seq) else atom.elem
            atom = Coll(atom.kind, old.join(item))
        if atom is None:
            return TOP
        out.append(atom)
    return atoms(out, value.soft)


def _with_pair(atom: DictAtom, key: Value, item: Value) -> DictAtom | None:
    if (key, item) in atom.items:
        return atom
    if len(atom.items) >= MAX_DICT_ITEMS:
        return None
    return DictAtom(atom.items + ((key, item),))
