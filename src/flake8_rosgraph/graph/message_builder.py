"""Reads :mod:`.messages`' facts off a finished analysis.

From the analyser's generic effects (``construct``, ``set_attribute`` and ``get_attribute`` on
instances of unmodelled library classes, the stubs' ``publish``) and from the return values of
service callbacks.
"""
from __future__ import annotations

from typing import Any

from ..absint.engine import Analysis, Effect
from ..absint.instances import CONSTRUCT, GET_ATTRIBUTE, SET_ATTRIBUTE
from ..absint.values import BoundMethod, Coll, Const, Extern, FuncAtom, Obj, Seq, Value, wrapped
from .messages import ValueShape, FieldStore, FieldRead, Construction, Publication, ServiceReturn, MessageFacts
from .model import Location

_SCALARS = {"bool": "bool", "int": "int", "float": "float", "str": "str", "bytes": "bytes",
            "NoneType": "none"}


def shapes(value: Value, analysis: Analysis, depth: int = 0) -> tuple[ValueShape, ...] | None:
    """What ``value`` may be, for the field rules; ``None``: not known well enough to judge.

    A *soft* value is a default the environment may override (a parameter's declared
    default, an argparse default): the running value is unknown, so it is never judged.
    """
    if value.is_top or value.soft or depth > 2:
        return None
    return tuple(sorted({_shape(atom, analysis, depth) for atom in value}, key=repr))


def _shape(atom: Any, analysis: Analysis, depth: int) -> ValueShape:
    if isinstance(atom, Const):
        kind = _SCALARS.get(atom.kind)
        return ValueShape(kind, atom.value) if kind else ValueShape("other")
    if isinstance(atom, Obj) and isinstance(atom.cls, Extern):
        qualname = atom.cls.qualname
        return ValueShape("instance", cls=qualname, modelled=qualname in analysis.library.classes)
    if isinstance(atom, Seq) and atom.kind in ("list", "tuple"):
        # A list's length is not known after ``append``/``extend`` (the analysis keeps the
        # literal's items); a tuple's is.
        length = len(atom.items) if atom.kind == "tuple" else None
        items: set[ValueShape] = set()
        for item in atom.items:
            found = shapes(item, analysis, depth + 1)
            if found is None:
                return ValueShape("sequence", atom.kind, length=length)
            items.update(found)
        return ValueShape("sequence", atom.kind, length=length, items=tuple(sorted(items, key=repr)))
    if isinstance(atom, Coll) and atom.kind in ("list", "tuple"):
        return ValueShape("sequence", atom.kind, items=shapes(atom.elem, analysis, depth + 1))
    return ValueShape("other")


def _location(eff: Effect) -> Location:
    return Location(eff.path, eff.line, eff.column)


def _class_names(value: Value) -> tuple[str, ...] | None:
    names = sorted({a.qualname for a in value if isinstance(a, Extern)})
    return tuple(names) if names and not value.is_top and len(names) == len(value.atoms) else None


def ros1_paths(analysis: Analysis) -> frozenset[str]:
    """The files of modules written for ROS 1: they import ``rospy`` and not ``rclpy``.

    A package built for both ROS versions (fkie's multi-agent suite: catkin's Python for ROS 1,
    C++ for ROS 2) keeps its rospy modules in the ROS 2 workspace. Their messages are genpy's,
    which take positional arguments and ints for ``byte`` and float fields: the ROS 2 message
    rules would misjudge every one of them.
    """
    def imports(module_name: str, top: str) -> bool:
        return any(name == top or name.startswith(top + ".")
                   for name in analysis.program.imports.get(module_name, ()))

    return frozenset(module.path for name, module in analysis.program.modules.items()
                     if imports(name, "rospy") and not imports(name, "rclpy"))


def message_facts(analysis: Analysis) -> MessageFacts:
    facts = MessageFacts([], [], [], [], [])
    ros1 = ros1_paths(analysis)
    # Every task's latest effects; the facts are deduplicated and sorted below.
    for eff in {eff for effects in analysis.effects.values() for eff in effects.values()}:
        if eff.path in ros1:
            continue
        if eff.kind == CONSTRUCT:
            message = (eff.arg("class").strings() or [""])[0]
            facts.constructions.append(Construction(_location(eff), message,
                                                    (eff.arg("positional").consts() or [0])[0]))
            for name, value in eff.args:
                if name.startswith("kw:"):
                    facts.stores.append(FieldStore(_location(eff), message, (name[3:],),
                                                   shapes(value, analysis), True))
        elif eff.kind == SET_ATTRIBUTE:
            path = tuple((eff.arg("path").strings() or [""])[0].split("."))
            for obj in eff.arg("object"):
                if isinstance(obj, Obj) and isinstance(obj.cls, Extern):
                    facts.stores.append(FieldStore(_location(eff), obj.cls.qualname, path,
                                                   shapes(eff.arg("value"), analysis), False))
        elif eff.kind == GET_ATTRIBUTE:
            if eff.arg("probed").consts() == [True]:
                continue  # ``if hasattr(msg, 'header'): msg.header…``: judged on no path
            path = tuple((eff.arg("path").strings() or [""])[0].split("."))
            facts.reads.extend(FieldRead(_location(eff), obj.cls.qualname, path)
                               for obj in eff.arg("object")
                               if isinstance(obj, Obj) and isinstance(obj.cls, Extern))
        elif eff.kind == "publish":
            facts.publications.append(Publication(_location(eff), shapes(eff.arg("msg"), analysis),
                                                  _class_names(eff.arg("type"))))
        elif eff.kind == "service":
            facts.service_returns.extend(_service_returns(analysis, eff))
    for bucket in (facts.stores, facts.reads, facts.constructions, facts.publications,
                   facts.service_returns):
        bucket[:] = sorted(set(bucket), key=repr)
    return facts


def _service_returns(analysis: Analysis, eff: Effect) -> list[ServiceReturn]:
    """What the callback of a ``service`` effect returns, over every context it was analysed in."""
    services = _class_names(eff.arg("type"))
    if services is None or len(services) != 1:
        return []
    out = []
    for atom in map(wrapped, eff.arg("callback")):
        if not isinstance(atom, (FuncAtom, BoundMethod)):
            continue
        func = analysis.program.functions[atom.fid]
        if func.is_generator:
            continue
        location = Location(func.module.path, getattr(func.node, "lineno", 1),
                            func.module.column(func.node))
        for task in analysis.effects:
            if task[0] == "fn" and task[1] == atom.fid:
                returned = analysis.heap.get(("ret", task))
                if returned is not None and not returned.is_bottom:
                    out.append(ServiceReturn(location, func.qualname, services[0],
                                             shapes(returned, analysis)))
    return out
