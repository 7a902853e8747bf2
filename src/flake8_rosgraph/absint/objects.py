"""Objects and classes: attribute lookup along the MRO, binding of methods, attribute stores.

Instance fields live in the engine's heap by allocation site; class attributes by
class; library classes answer from their models. ``super()`` resolves along the
receiver's C3 linearisation.
"""
from __future__ import annotations


import sys

from .values import (BOTTOM, TOP, Atom, BoundMethod, ClassAtom, Coll, Const, DictAtom, Extern,
                     ExternBound, FuncAtom, ModuleAtom, Obj, Record, Seq, SuperAtom, Value, atoms,
                     const)
from .calls import OBJECT_NEW, Args
from .class_attrs import data_attribute_names
from .enums import ENUM_BASES, MIXIN_BASES, member_names, member_site
from .fieldclasses import FIELD_BASES, Field, decorated_fields, own_fields

#: The attributes that name a class.
_NAME_ATTRS = ("__module__", "__name__", "__qualname__")
#: Top-level modules of the standard library (``builtins`` included): an ``abc.ABC`` or
#: ``threading.Thread`` base is no unresolved library class.
_STDLIB = frozenset(sys.stdlib_module_names) | {"builtins"}
#: Libraries whose classes add no ``__class_getitem__`` or metaclass ``__getitem__`` of
#: their own to a workspace class deriving from them (``Generic``, ``Protocol``, ``ABC``).
_GENERIC_SAFE = frozenset({"typing", "typing_extensions", "abc", "collections"})


class ObjectSemantics:
    """Attribute and class semantics, mixed into :class:`~.interpreter.Interpreter`."""

    def load_attr(self, value: Value, attr: str) -> Value:
        if value.is_top:
            return TOP
        out = BOTTOM
        for atom in value:
            found = self._attr_of(atom, attr)
            if found.is_bottom and value.soft:
                # An overridable default without the attribute (``args.trace.resolve()``
                # with ``--trace`` defaulting to None): the value given instead has it.
                found = TOP
            out = out.join(found)
            if out.is_top and out.is_saturated:
                # Only the saturated ⊤ absorbs what the other atoms give: a ⊤ that keeps
                # known names still takes theirs (stopping there made the result depend on
                # the set's iteration order, which varies from run to run).
                return out
        return out

    def _attr_of(self, atom: Atom, attr: str) -> Value:
        task = self.frame.task
        if isinstance(atom, Obj):
            if attr == "__class__":
                return atoms([atom.cls])
            field_value = self.an.read(("a", atom.site, attr), task)
            if not field_value.is_bottom and self.is_annotated(attr) and attr in self.field_names(atom.cls):
                return field_value  # its __init__ always sets it: the class-level value is a default
            found = self.class_attr(self.mro(atom.cls), attr, atom)
            if found is None:
                if attr == "__module__" and field_value.is_bottom and isinstance(atom.cls, Extern):
                    return self._class_name_attr(atom.cls, attr)
                if field_value.is_bottom and not attr.startswith("__"):
                    # Python calls ``__getattr__`` for what the object and its class lack: a
                    # wrapper forwarding to the object it holds (``getattr(self._node, name)``).
                    forward = self.class_attr(self.mro(atom.cls), "__getattr__", atom)
                    if forward is not None:
                        return self.call(forward, Args([atoms([Const.of(attr)])], {}, False), None)
                if field_value.is_bottom:
                    stand_in = self.lib.stand_in(attr)
                    if stand_in is not None and isinstance(atom.cls, ClassAtom) \
                            and self.unresolved_base(atom.cls) is not None:
                        # Only a call of the right shape is taken for the model's (calls.py).
                        return atoms([ExternBound(atom, f"{stand_in.owner}.{attr}")])
                if field_value.is_bottom and not self._all_user(atom.cls) and (
                        attr not in self.program.stored_attrs or isinstance(atom.cls, Extern)):
                    # Nothing here assigns it: the library's attribute. An instance of a
                    # library class (a message) has every attribute the library gave it,
                    # whatever the workspace stores on other objects under that name.
                    return TOP
                return field_value
            return field_value.join(found)
        if isinstance(atom, ClassAtom):
            member = self.enum_member(atom, attr)
            if member is not None:
                return member
            found = self.class_attr(self.mro(atom), attr, None)
            if found is None and attr in _NAME_ATTRS:
                klass = self.program.classes[atom.cid]
                return const({"__module__": klass.module.name, "__name__": klass.node.name,
                              "__qualname__": klass.qualname}[attr])
            return TOP if found is None else found
        if isinstance(atom, SuperAtom):
            cls_of = atom.receiver.cls if isinstance(atom.receiver, Obj) else atom.receiver
            order = self.mro(cls_of)
            here = ClassAtom(atom.cid)
            if here in order:
                order = order[order.index(here) + 1:]
            found = self.class_attr(order, attr, atom.receiver)
            if found is None and attr == "__new__":
                return atoms([Extern(OBJECT_NEW)])
            return TOP if found is None else found
        if isinstance(atom, ModuleAtom):
            return self.import_member(atom.name, attr, attribute=True)
        if isinstance(atom, Extern):
            if attr in _NAME_ATTRS:
                return self._class_name_attr(atom, attr)
            model = self.lib.classes.get(atom.qualname)
            if model is not None and self.lib.method(atom.qualname, attr):
                return atoms([Extern(f"{atom.qualname}.{attr}")])
            return self.extern(f"{atom.qualname}.{attr}")
        if isinstance(atom, Record):
            field_value = atom.field(attr)
            if field_value is not None:
                return field_value
            if self.lib.method(atom.qualname, attr):
                return atoms([ExternBound(atom, f"{atom.qualname}.{attr}")])
            return TOP
        if isinstance(atom, Const) and isinstance(atom.value, str):
            return atoms([ExternBound(atom, "builtins.str." + attr)])
        if atom == Const.of(None):
            return BOTTOM  # AttributeError at run time: no value flows on
        if isinstance(atom, (Seq, Coll, DictAtom)):
            return atoms([ExternBound(atom, "builtins.container." + attr)])
        return TOP

    def _class_name_attr(self, cls: Extern, attr: str) -> Value:
        """``__module__``/``__name__``/``__qualname__`` of a library class, where the library
        knows them (code that dispatches on them then takes only the branch that runs)."""
        identity = self.lib.class_identity(cls.qualname)
        if identity is None:
            return self.extern(f"{cls.qualname}.{attr}")
        module, name = identity
        return const(module if attr == "__module__" else name)

    def enum_members(self, cls: ClassAtom) -> tuple[str, ...] | None:
        """The member names of ``cls`` when it is a workspace ``Enum`` whose members are
        objects (not ``str``/``int`` mixins, see :mod:`.enums`), in the class body's order."""
        order = self.mro(cls)
        libraries = {a.qualname for a in order if isinstance(a, Extern)}
        if not libraries & ENUM_BASES or libraries & MIXIN_BASES:
            return None
        return member_names(self.program.classes[cls.cid])

    def enum_member(self, cls: ClassAtom, attr: str) -> Value | None:
        """``Mode.NAVIGATION``: the member object, whose ``value`` is what the class body
        assigned and whose ``name`` is ``attr``; ``None`` when ``attr`` is no member."""
        members = self.enum_members(cls)
        if members is None or attr not in members:
            return None
        klass = self.program.classes[cls.cid]
        assigned = self.an.read(("k", cls.cid, attr), self.frame.task)
        if assigned.is_bottom:
            return BOTTOM  # the class body has not run yet
        site = member_site(klass, attr)
        for field_name, field_value in (("value", assigned), ("_value_", assigned),
                                        ("name", const(attr)), ("_name_", const(attr))):
            self.an.write(("a", site, field_name), field_value)
        return atoms([Obj(site, cls)])

    def is_generic_alias(self, cls: ClassAtom) -> bool:
        """Whether ``cls[...]`` is a generic alias of workspace class ``cls`` (``Base[T]`` as a
        base class, ``Connector[Msg]()``): Python's ``typing`` makes the alias stand for the
        class, as a base (``__mro_entries__``) and when called. Not taken where the subscript
        may run code of its own: a metaclass (an ``Enum``'s ``Color['RED']`` is a member), a
        ``__class_getitem__``, or a library class other than ``typing``'s and ``abc``'s above it."""
        for atom in self.mro(cls):
            if isinstance(atom, Extern):
                if atom.qualname != "builtins.object" and atom.qualname.partition(".")[0] not in _GENERIC_SAFE:
                    return False
                continue
            if not isinstance(atom, ClassAtom):
                return False
            klass = self.program.classes[atom.cid]
            if "__class_getitem__" in klass.methods or any(
                    kw.arg == "metaclass" for kw in klass.node.keywords):
                return False
        return True

    def init_fields(self, cls: ClassAtom) -> tuple[list[Field], bool] | None:
        """The fields ``cls``'s ``__init__`` is written from (see :mod:`.fieldclasses`), base
        classes' first, and whether arguments bind to them by position too (a dataclass, a
        ``NamedTuple``) or by keyword only (pydantic, a library base no stub models); ``None``
        when the workspace's own ``__init__`` (or a modelled library's) comes first."""
        order = self.mro(cls)
        for atom in order:
            if isinstance(atom, ClassAtom):
                klass = self.program.classes[atom.cid]
                if decorated_fields(klass):
                    return self._merged_fields(order), True
                if "__init__" in klass.methods:
                    return None
                continue
            if not isinstance(atom, Extern) or atom.qualname == "builtins.object":
                return None
            if atom.qualname in FIELD_BASES:
                return self._merged_fields(order), atom.qualname == "typing.NamedTuple"
            if _unresolved(atom, self.lib):
                return self._merged_fields(order), False
            if self.lib.method(atom.qualname, "__init__") is not None:
                return None
        return None

    def is_annotated(self, attr: str) -> bool:
        """Whether some class body the program has walked annotates ``attr`` (classes are
        numbered as their modules are first needed, so the set grows with them)."""
        classes = self.program.classes
        while self._annotated_upto < len(classes):
            self._annotated.update(f.name for f in self._fields_of(self._annotated_upto))
            self._annotated_upto += 1
        return attr in self._annotated

    def field_names(self, cls: Atom) -> frozenset[str]:
        found = self.init_fields(cls) if isinstance(cls, ClassAtom) else None
        return frozenset(f.name for f in found[0] if f.init) if found else frozenset()

    def _merged_fields(self, order: list[Atom]) -> list[Field]:
        merged: dict[str, Field] = {}
        for atom in reversed(order):
            if isinstance(atom, ClassAtom):
                for found in self._fields_of(atom.cid):
                    merged[found.name] = found
        return list(merged.values())

    def _fields_of(self, cid: int) -> list[Field]:
        known = self._own_fields.get(cid)
        if known is None:
            known = self._own_fields[cid] = own_fields(self.program.classes[cid])
        return known

    def unresolved_base(self, cls: Atom) -> str | None:
        """The first base class of workspace class ``cls`` (along its MRO) that is imported from
        a library no stub models and that is not the standard library's; ``None`` if none."""
        return next((b.qualname for b in self.mro(cls) if _unresolved(b, self.lib)), None)

    def _all_user(self, cls: Atom) -> bool:
        return all(isinstance(c, ClassAtom) or c == Extern("builtins.object")
                   for c in self.mro(cls))

    def class_attr(self, order: list[Atom], attr: str, receiver: Atom | None) -> Value | None:
        """Look ``attr`` up along a method resolution order; bind functions to ``receiver``."""
        for cls in order:
            if isinstance(cls, ClassAtom):
                value = self.an.read(("k", cls.cid, attr), self.frame.task)
                if value.is_bottom:
                    continue
                return self._bind(value, receiver, cls)
            model_method = self.lib.classes.get(cls.qualname)
            if model_method is not None and attr in model_method.methods:
                qual = f"{cls.qualname}.{attr}"
                return atoms([ExternBound(receiver, qual) if receiver is not None else Extern(qual)])
            constant = self.lib.constants.get(f"{cls.qualname}.{attr}")
            if constant is not None:
                return constant
        return None

    def _bind(self, value: Value, receiver: Atom | None, owner: ClassAtom) -> Value:
        if value.is_top:
            return value
        out = []
        for atom in value:
            if isinstance(atom, FuncAtom):
                func = self.program.functions[atom.fid]
                kind = func.kind
                if func.setter:
                    continue  # the property's getter gives what reading the attribute does
                if kind == "staticmethod":
                    out.append(atom)
                elif kind == "classmethod":
                    recv = receiver.cls if isinstance(receiver, Obj) else owner
                    out.append(BoundMethod(recv, atom.fid))
                elif receiver is None:
                    out.append(atom)
                elif kind == "property":
                    return self.call(atoms([BoundMethod(receiver, atom.fid)]), Args([], {}, False),
                                     None)
                else:
                    out.append(BoundMethod(receiver, atom.fid))
            else:
                out.append(atom)
        return atoms(out)

    def store_attr(self, target: Value, attr: str, value: Value) -> None:
        for atom in target:
            if isinstance(atom, Obj):
                setters = self._setters(atom, attr)
                if setters:  # ``scope.executor = executor`` runs the property's setter
                    for fid in setters:
                        self.call(atoms([BoundMethod(atom, fid)]), Args([value], {}, False), None)
                    continue
                self.an.write(("a", atom.site, attr), value)
            elif isinstance(atom, ClassAtom):
                self.an.write(("k", atom.cid, attr), value)
            elif isinstance(atom, ModuleAtom):
                self.an.write(("g", atom.name, attr), value)

    def store_any_attr(self, target: Value, value: Value) -> None:
        """``setattr(target, name, value)`` with a name the analysis does not know: ``value``
        joins every data attribute the workspace classes of ``target`` name in their source
        (:mod:`.class_attrs`), so that none keeps its default as a sure value."""
        for atom in () if target.is_top else target:
            cls = atom.cls if isinstance(atom, Obj) else atom
            if not isinstance(cls, ClassAtom):
                continue
            names: set[str] = set()
            for klass in self.mro(cls):
                if isinstance(klass, ClassAtom):
                    names |= data_attribute_names(self.program.classes[klass.cid])
            for attr in sorted(names):
                if isinstance(atom, Obj):
                    self.an.write(("a", atom.site, attr), value)
                else:
                    self.an.write(("k", atom.cid, attr), value)

    def _setters(self, obj: Obj, attr: str) -> list[int]:
        """The property setters ``obj.<attr> = …`` runs: those of the first workspace class
        along the MRO that binds ``attr``."""
        for cls in self.mro(obj.cls):
            if not isinstance(cls, ClassAtom):
                continue
            bound = self.an.read(("k", cls.cid, attr), self.frame.task)
            if bound.is_bottom:
                continue
            return [a.fid for a in bound if isinstance(a, FuncAtom) and self.program.functions[a.fid].setter] \
                if not bound.is_top else []
        return []

    # -- classes ----------------------------------------------------------------------------
    def user_bases(self, cid: int) -> list[int]:
        return analysed_user_bases(self.an.heap, cid)

    def library_bases(self, cid: int) -> list[str]:
        return [a.qualname for a in self.mro(ClassAtom(cid)) if isinstance(a, Extern)]

    def mro(self, cls: Atom) -> list[Atom]:
        """C3 linearisation over user classes (bases as analysed) and modelled library classes.

        Memoised per class together with the analysed bases it was computed from; a hit
        still reads those bases so that the current task is re-run if they grow.
        """
        if isinstance(cls, Extern):
            return self._library_mro(cls)
        if not isinstance(cls, ClassAtom):
            return []
        memo = self._mro_memo.get(cls.cid)
        if memo is not None and all(self._bases_value(cid) == value for cid, value in memo[1]):
            return memo[0]
        used: list[tuple[int, Value]] = []
        result = self._linearise(cls, frozenset(), used)
        self._mro_memo[cls.cid] = (result, tuple(used))
        return result

    def _library_mro(self, cls: Extern) -> list[Atom]:
        """The MRO of a library class as atoms, built once per class (the model is fixed)."""
        known = self._extern_mro.get(cls.qualname)
        if known is None:
            known = self._extern_mro[cls.qualname] = [Extern(q) for q in self.lib.mro(cls.qualname)]
        return known

    def _bases_value(self, cid: int) -> Value:
        key = ("bases", cid)
        return self.an.read(key, self.frame.task) if self.frame else self.an.heap.get(key, BOTTOM)

    def _linearise(self, cls: Atom, seen: frozenset, used: list) -> list[Atom]:
        if isinstance(cls, Extern):
            return self._library_mro(cls)
        if not isinstance(cls, ClassAtom) or cls in seen:
            return []
        bases_value = self._bases_value(cls.cid)
        used.append((cls.cid, bases_value))
        bases = _flatten_bases(bases_value)
        seqs = [self._linearise(b, seen | {cls}, used) for b in bases] + [bases]
        return [cls] + _c3_merge(seqs)

def analysed_user_bases(heap: dict, cid: int) -> list[int]:
    """The workspace base classes of class ``cid``, as the analysis evaluated them."""
    return [a.cid for a in _flatten_bases(heap.get(("bases", cid), BOTTOM))
            if isinstance(a, ClassAtom)]


def analysed_unresolved_base(heap: dict, lib, cid: int) -> str | None:
    """The first unresolved base class (see ``unresolved_base``) of workspace class ``cid`` or
    of its workspace bases, depth-first, as the analysis evaluated them; for reports."""
    todo, seen = [cid], set()
    while todo:
        cur = todo.pop(0)
        if cur in seen:
            continue
        seen.add(cur)
        for atom in _flatten_bases(heap.get(("bases", cur), BOTTOM)):
            if _unresolved(atom, lib):
                return atom.qualname
            if isinstance(atom, ClassAtom):
                todo.append(atom.cid)
    return None


def _unresolved(atom: Atom, lib) -> bool:
    """A library class no stub models, outside the standard library."""
    return isinstance(atom, Extern) and atom.qualname not in lib.classes \
        and atom.qualname.partition(".")[0] not in _STDLIB


def _flatten_bases(value: Value) -> list[Atom]:
    """Base classes in source order from the analysed ``(base, …)`` tuples of a class."""
    out: list[Atom] = []
    for seq in (a for a in value if isinstance(a, Seq)):
        for item in seq.items:
            for atom in item:
                if isinstance(atom, (ClassAtom, Extern)) and atom not in out:
                    out.append(atom)
    return out


def _c3_merge(seqs: list[list[Atom]]) -> list[Atom]:
    seqs = [list(s) for s in seqs if s]
    out: list[Atom] = []
    while seqs:
        for seq in seqs:
            head = seq[0]
            if not any(head in s[1:] for s in seqs):
                break
        else:  # inconsistent hierarchy: fall back to depth-first order
            for seq in seqs:
                out.extend(x for x in seq if x not in out)
            return out
        out.append(head)
        seqs = [[x for x in s if x != head] for s in seqs]
        seqs = [s for s in seqs if s]
    return out
