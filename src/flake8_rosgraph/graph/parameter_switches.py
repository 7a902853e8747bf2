"""Entities a library creates only when a parameter is set to true (rclpy's ``/clock``
subscription exists only with ``use_sim_time``).

An effect carrying ``when_true`` (a constant parameter name) and ``in_parameters`` (a list
of ``rclpy.parameter.Parameter`` records: a node's ``parameter_overrides``, the argument of
``set_parameters``) becomes an entity only when that list certainly sets the parameter to
``True``: in every possible list, an entry that is that parameter in every alternative, with a
value that is exactly ``True`` and not an overridable default. Anything less creates nothing:
an unknown list or value says nothing about the switch, and inventing the entity would be
worse than missing it.
"""
from __future__ import annotations

from ..absint.engine import Effect
from ..absint.values import Record, Seq, Value

#: The library class whose records name parameters (``Parameter(name, type_, value)``).
PARAMETER_RECORD = "rclpy.parameter.Parameter"


def switched_off(eff: Effect) -> bool:
    """Whether ``eff`` depends on a parameter switch that is not certainly on."""
    return "when_true" in dict(eff.args) and not switched_on(eff.arg("when_true"), eff.arg("in_parameters"))


def switched_on(name: Value, parameters: Value) -> bool:
    """Whether every possible list in ``parameters`` sets the parameter ``name`` to ``True``."""
    names = name.strings()
    if not names or len(names) != 1 or parameters.is_top or parameters.is_bottom:
        return False
    return all(_sets_true(atom, names[0]) for atom in parameters)


def _sets_true(atom, name: str) -> bool:
    """A list of known length holding the entry (a collection of unknown length may be empty)."""
    return isinstance(atom, Seq) and any(_is_true_entry(item, name) for item in atom.items)


def _is_true_entry(item: Value, name: str) -> bool:
    if item.is_top or item.is_bottom:
        return False
    for atom in item:
        if not isinstance(atom, Record) or atom.qualname != PARAMETER_RECORD:
            return False
        field_name, value = atom.field("name"), atom.field("value")
        if field_name is None or field_name.strings() != [name] or value is None \
                or value.soft or value.consts() != [True]:
            return False
    return True
