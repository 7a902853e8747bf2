"""Facts as plain JSON and back, for the on-disk cache (never pickle).

The front ends' facts are dataclasses of strings, numbers, lists, tuples, dicts and other
such dataclasses. JSON has lists, strings, numbers, booleans and null; everything else is
an object with one tag saying what it is:

* ``{"t": [...]}`` a tuple, ``{"f": [...]}`` a frozenset (in a stable order),
  ``{"m": [[key, value], ...]}`` a dict (any keys, insertion order kept), ``{"n": "inf"}`` a
  float JSON cannot write (``inf``, ``-inf``, ``nan``);
* ``{"c": "graph.model.Entity", "v": [...]}`` a dataclass of one of :data:`FACT_MODULES`:
  its compared fields in order. Fields left out of comparisons are the producer's working
  handles (an analysis's function number), not facts: they are not stored and come back as
  their default.

Decoding builds only those classes, and encoding refuses any other type (:class:`NotAFact`):
a fact the format cannot say is never stored wrong — its group is analysed again next time.
"""
from __future__ import annotations

import dataclasses
import importlib
import json
import math
from typing import Any, Callable

#: The modules whose dataclasses are facts (relative to the package).
FACT_MODULES = ("graph.model", "graph.usage", "graph.messages", "launch.actions", "launch.model",
                "launch.packages", "python_facts", "metadata", "interfaces.catalogue",
                "security.policy")


#: The floats JSON cannot write, as ``repr`` gives them.
_NON_FINITE = frozenset({"inf", "-inf", "nan"})


class NotAFact(ValueError):
    """A value the format cannot hold, or text that is not an encoded fact."""


def _classes() -> dict[str, type]:
    out = {}
    for name in FACT_MODULES:
        module = importlib.import_module(f"{__package__}.{name}")
        for value in vars(module).values():
            if isinstance(value, type) and dataclasses.is_dataclass(value) \
                    and value.__module__ == module.__name__:
                out[f"{name}.{value.__qualname__}"] = value
    return out


_CLASSES: dict[str, type] | None = None
#: Class -> its tag and stored fields (the compared ones, in order).
_FIELDS: dict[type, tuple[str, tuple[str, ...]]] = {}
#: Classes whose stored fields are their first ``__init__`` parameters, in order: built positionally.
_POSITIONAL: set[type] = set()


def _registry() -> dict[str, type]:
    global _CLASSES
    if _CLASSES is None:
        _CLASSES = _classes()
        for tag, cls in _CLASSES.items():
            fields = dataclasses.fields(cls)
            stored = tuple(f.name for f in fields if f.compare)
            _FIELDS[cls] = (tag, stored)
            if stored == tuple(f.name for f in fields if f.init)[:len(stored)]:
                _POSITIONAL.add(cls)
    return _CLASSES


def to_obj(value: Any) -> Any:
    """``value`` as JSON-ready data; :class:`NotAFact` for a type the format does not hold."""
    if value is None or isinstance(value, (bool, int, str)):
        return value
    if isinstance(value, float):
        return value if math.isfinite(value) else {"n": repr(value)}  # JSON has no inf or nan
    if isinstance(value, list):
        return [to_obj(item) for item in value]
    if isinstance(value, tuple):
        return {"t": [to_obj(item) for item in value]}
    if isinstance(value, frozenset):
        return {"f": sorted((to_obj(item) for item in value), key=_stable)}
    if isinstance(value, dict):
        return {"m": [[to_obj(k), to_obj(v)] for k, v in value.items()]}
    _registry()
    known = _FIELDS.get(type(value))
    if known is None:
        raise NotAFact(f"not a fact: {type(value).__name__}")
    tag, names = known
    return {"c": tag, "v": [to_obj(getattr(value, name)) for name in names]}


def _stable(obj: Any) -> str:
    return json.dumps(obj, sort_keys=True)


#: JSON values that stand for themselves: decoded without a call (most fields are such).
_PLAIN = frozenset({str, int, float, bool, type(None)})


def from_obj(obj: Any) -> Any:
    """The value :func:`to_obj` made ``obj`` from; :class:`NotAFact` for anything else."""
    kind = type(obj)
    if kind in _PLAIN:
        return obj
    if kind is list:
        return _items(obj)
    found = _untagged(obj, _items) if kind is dict else _NOT_A_TAG
    if found is _NOT_A_TAG:
        raise NotAFact("not an encoded fact")
    return found


#: What :func:`_untagged` gives for an object that is no tag.
_NOT_A_TAG = object()


def _untagged(obj: dict, items: Callable[[list], list]) -> Any:
    """What the tagged object ``obj`` stands for, its members made values by ``items``
    (:func:`_items` on parsed JSON; nothing when the parser decoded them already, see
    :func:`loads_entry`); :data:`_NOT_A_TAG` for an object that is no tag."""
    size = len(obj)
    if size == 2 and "c" in obj and "v" in obj:
        return _instance(obj, items(_list(obj["v"])))
    if size != 1:
        return _NOT_A_TAG
    if "t" in obj:
        return tuple(items(_list(obj["t"])))
    if "f" in obj:
        return _hashed(frozenset, items(_list(obj["f"])))
    if "m" in obj:
        pairs = [_list(pair) for pair in _list(obj["m"])]
        if any(len(pair) != 2 for pair in pairs):
            raise NotAFact("not a key-value pair")
        return _hashed(dict, [items(pair) for pair in pairs])
    if "n" in obj:
        if obj["n"] not in _NON_FINITE:
            raise NotAFact("not a non-finite number")
        return float(obj["n"])
    return _NOT_A_TAG


def _instance(obj: dict, values: list) -> Any:
    """The fact ``obj`` tags, from its field ``values`` (decoded)."""
    cls = _registry().get(obj["c"]) if isinstance(obj["c"], str) else None
    if cls is None:
        raise NotAFact(f"not a fact class: {obj['c']!r}")
    names = _FIELDS[cls][1]
    if len(values) != len(names):
        raise NotAFact(f"{obj['c']}: {len(values)} values for {len(names)} fields")
    try:
        if cls in _POSITIONAL:
            return cls(*values)
        return cls(**dict(zip(names, values)))
    except TypeError as exc:  # a field without a default not stored: not a fact class
        raise NotAFact(str(exc)) from exc


def _items(values: list) -> list:
    """:func:`from_obj` of each of ``values``; plain ones are taken as they are, without a call."""
    return [value if type(value) in _PLAIN else from_obj(value) for value in values]


def _list(obj: Any) -> list:
    if not isinstance(obj, list):
        raise NotAFact("not a list")
    return obj


def loads_entry(text: str) -> dict:
    """A JSON object whose members hold encoded facts (``{"key": …, "facts": to_obj(facts)}``),
    with the facts decoded during the parse: what :func:`from_obj` of each member gives, about
    twice as fast (an edited workspace reads every kept group's facts, on every pre-commit run).
    :class:`NotAFact` for anything :func:`from_obj` refuses, and for an untagged object anywhere
    but at the top."""
    untagged: list[dict] = []

    def decoded(obj: dict) -> Any:
        found = _untagged(obj, _as_decoded)
        if found is _NOT_A_TAG:
            untagged.append(obj)
            return obj
        return found

    top = json.loads(text, object_hook=decoded)
    if len(untagged) != 1 or untagged[0] is not top:
        raise NotAFact("not an object of encoded facts")
    return top


def _as_decoded(values: list) -> list:
    return values


def _hashed(make: type, items: list) -> Any:
    try:
        return make(items)
    except TypeError as exc:  # an unhashable member: no frozenset or dict the encoder wrote
        raise NotAFact(str(exc)) from exc
