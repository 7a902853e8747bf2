"""What a function just stored on an object is what it reads back there.

The heap keeps one value per attribute of an abstract object, joined over every store in
the program: ``self.topic`` read in ``__init__`` right after ``self.topic = '/chatter'`` is
also whatever a callback or ``main`` stores there later. Python reads the value stored last,
so a function's own store, on every path to the read, is the value — as long as nothing
else can have stored one in between.

The store is remembered in the function's environment, under ``.<variable>.<attribute>``
(no Python name starts with a dot), so it follows the control flow: at a merge it is kept
only when every path stored (the environments' join, see ``join_remembered``), and it is
forgotten when the variable is bound again, when the attribute is stored through another
variable (which may be the same object), and when code that may store attributes runs: a
call of workspace code or of an unknown callee, a library call that runs an executor's
callbacks (a model with ``blocking``), ``setattr``, a ``yield`` or an ``await``.

Only attributes that hold what was stored are remembered: of workspace-class instances whose
classes bind no property, descriptor or method under that name and define no
``__setattr__``. The heap is written as before; only this function's reads change.
"""
from __future__ import annotations

import ast

from .values import BOTTOM, BoundMethod, ClassAtom, Extern, ExternBound, FuncAtom, Obj, Value

#: The environment key that says a function remembers attributes (see ``join_remembered``).
MARK = "."
#: Library callables that store attributes on the object they are given.
_STORING_BUILTINS = frozenset({"builtins.setattr", "builtins.delattr", "builtins.exec"})


def key(variable: str, attr: str) -> str:
    return f".{variable}.{attr}"


def is_remembered(name: str) -> bool:
    """Whether an environment entry is a remembered attribute (or the mark), not a variable."""
    return name[:1] == "."


def join_remembered(out: dict, old: dict, new: dict) -> None:
    """Keep in ``out`` (the join of ``old`` and ``new``) only the attributes both remember."""
    if MARK not in old and MARK not in new:
        return
    for name in [n for n in out if is_remembered(n) and (n not in old or n not in new)]:
        del out[name]


class AttributeFlow:
    """Remembered attribute stores, mixed into :class:`~.interpreter.Interpreter`."""

    def remember_attribute(self, target: ast.Attribute, holder: Value, value: Value) -> None:
        """After ``target = value`` (``holder`` the object): remember it where it is read back
        as stored; forget what other variables remember of the attribute."""
        frame = self.frame
        if frame.func is None or frame.cls is not None:
            return
        self._forget(lambda name: name.endswith("." + target.attr))
        variable = target.value.id if isinstance(target.value, ast.Name) else None
        if variable is None or variable not in frame.func.locals or frame.comp \
                or not self._holds_what_is_stored(holder, target.attr):
            return
        frame.env[MARK] = BOTTOM
        frame.env[key(variable, target.attr)] = value

    def remembered_attribute(self, node: ast.Attribute) -> Value | None:
        """What this function stored last at ``node`` on every path here, if it remembers."""
        env = self.frame.env
        if MARK not in env or not isinstance(node.value, ast.Name) or self.frame.comp:
            return None
        return env.get(key(node.value.id, node.attr))

    def forget_variable(self, variable: str) -> None:
        """``variable`` is bound again: it is another object now."""
        prefix = f".{variable}."
        self._forget(lambda name: name.startswith(prefix))

    def forget_attributes(self) -> None:
        """Code that may store attributes ran."""
        self._forget(lambda name: True)

    def forget_for_call(self, func: Value) -> None:
        """Before calling ``func``: forget everything if it may store attributes now."""
        if MARK in self.frame.env and self._may_store(func):
            self.forget_attributes()

    def _forget(self, which) -> None:
        env = self.frame.env
        if MARK in env:
            for name in [n for n in env if is_remembered(n) and n != MARK and which(n)]:
                del env[name]

    def _may_store(self, func: Value) -> bool:
        """Whether calling ``func`` may run code that stores attributes before it returns:
        workspace code, an unknown callee, ``setattr``, or a library model that spins an
        executor (whose callbacks run meanwhile)."""
        if func.is_top:
            return True
        for atom in func:
            if isinstance(atom, Extern):
                if atom.qualname in _STORING_BUILTINS:
                    return True
                owner, _, name = atom.qualname.rpartition(".")
                model = self.lib.functions.get(atom.qualname) or (
                    self.lib.method(owner, name) if owner in self.lib.classes else None)
            elif isinstance(atom, ExternBound):
                owner, _, name = atom.qualname.rpartition(".")
                model = self.lib.method(owner, name)
            else:
                return True
            if model is not None and model.blocking is not None:
                return True
        return False

    def _holds_what_is_stored(self, holder: Value, attr: str) -> bool:
        """Whether reading ``attr`` back from every object ``holder`` may be gives the value
        stored: instances of workspace classes that bind nothing but plain data under
        ``attr`` and define no ``__setattr__``."""
        if holder.is_top or holder.is_bottom:
            return False
        for atom in holder:
            if not isinstance(atom, Obj) or not isinstance(atom.cls, ClassAtom):
                return False
            for cls in self.mro(atom.cls):
                if not isinstance(cls, ClassAtom):
                    continue
                if not self.an.read(("k", cls.cid, "__setattr__"), self.frame.task).is_bottom:
                    return False
                bound = self.an.read(("k", cls.cid, attr), self.frame.task)
                if bound.is_top or any(isinstance(a, (Obj, FuncAtom, BoundMethod)) for a in bound):
                    return False
        return True
