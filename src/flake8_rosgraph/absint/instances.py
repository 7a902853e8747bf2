"""Facts about instances of library classes the stubs do not model: how code builds them and
which attributes it stores on them.

The analyser does not know what an unmodelled class (a message, a dataclass of some library)
accepts, but a consumer that does can check what the code does with it. Two effects carry
it, recorded like stub effects at the site in the workspace:

* ``construct``: a call of an unmodelled library class. Arguments: ``class`` (its qualified
  name), ``object`` (the new instance), ``positional`` (how many positional arguments),
  ``star`` (whether ``*``/``**`` unpacking hides some) and ``kw:<name>`` per keyword.
* ``set_attribute``: ``x.a.b = v`` where ``x`` — or ``x.a`` — is such an instance.
  Arguments: ``object`` (the instances the chain starts from), ``path`` (the attribute
  chain below them, ``"a.b"``) and ``value``. The chain lets ``msg.header.stamp = t`` be
  checked although nothing modelled what ``msg.header`` holds.
* ``get_attribute``: a read ``x.a.b``, the same way (``object``, ``path``), and ``probed``:
  whether the function tests that attribute with ``hasattr``/``getattr`` (the read may be
  on the path where it exists).

Nothing here gives these facts a meaning; they are data for whoever reads effects.
"""
from __future__ import annotations

import ast

from .calls import Args
from .engine import Effect
from .values import Extern, Obj, Value, atoms, const

CONSTRUCT = "construct"
SET_ATTRIBUTE = "set_attribute"
GET_ATTRIBUTE = "get_attribute"
#: Longest attribute chain followed above a store (``a.b.c.d.e = v``).
MAX_CHAIN = 6


class InstanceFacts:
    """Recording of these effects, mixed into :class:`~.interpreter.Interpreter`."""

    def record_construct(self, obj: Obj, args: Args, node: ast.AST | None) -> None:
        if node is None:
            return
        values = [("class", const(obj.cls.qualname)), ("object", atoms([obj])),
                  ("positional", const(len(args.pos))), ("star", const(args.star))]
        values.extend((f"kw:{name}", value) for name, value in sorted(args.kw.items()))
        self._record(CONSTRUCT, tuple(values), node)

    def record_attribute_store(self, target: ast.Attribute, holder: Value, value: Value) -> None:
        if holder.atoms and not any(type(a) is Obj and type(a.cls) is Extern for a in holder.atoms):
            return  # as in ``record_attribute_load``
        found, path = self._chain_root(target, holder)
        if found:
            self._record(SET_ATTRIBUTE, (("object", atoms(found)), ("path", const(path)),
                                         ("value", value)), target)

    def record_attribute_load(self, node: ast.Attribute, holder: Value) -> None:
        if holder.atoms and not any(type(a) is Obj and type(a.cls) is Extern for a in holder.atoms):
            return  # a known holder without library instances ends the chain at once (``_chain_root``)
        found, path = self._chain_root(node, holder)
        if found:
            probed = path.split(".", 1)[0] in self._probed_names()
            self._record(GET_ATTRIBUTE, (("object", atoms(found)), ("path", const(path)),
                                         ("probed", const(probed))), node)

    def _probed_names(self) -> frozenset[str]:
        """Attribute names the running function tests before use (``hasattr(x, 'header')``,
        ``getattr(x, 'header', None)``): a read of one may be on an object without it."""
        task = self.frame.task
        body = self.program.functions[task[1]].node if task[0] == "fn" else self.frame.module.tree
        known = self._probes.get(id(body))
        if known is None:
            known = self._probes[id(body)] = frozenset(
                call.args[1].value for call in ast.walk(body)
                if isinstance(call, ast.Call) and isinstance(call.func, ast.Name)
                and call.func.id in ("hasattr", "getattr") and len(call.args) >= 2
                and isinstance(call.args[1], ast.Constant) and isinstance(call.args[1].value, str))
        return known

    def _chain_root(self, node: ast.Attribute, holder: Value) -> tuple[list[Obj], str]:
        """The unmodelled instances ``node``'s attribute chain starts from (nearest first),
        and the chain below them (``"header.stamp"``)."""
        path = [node.attr]
        expr: ast.expr = node.value
        current = holder
        for _ in range(MAX_CHAIN):
            found = self._unmodelled_instances(current)
            if found:
                return found, ".".join(path)
            # Go up only through what the analysis did not follow (an attribute it does not
            # know, or one only other objects received): a known holder ends the chain.
            if not current.is_top and not current.is_bottom:
                break
            if not isinstance(expr, ast.Attribute) or not _plain_chain(expr.value):
                break
            path.insert(0, expr.attr)
            expr = expr.value
            current = self.eval(expr)
        return [], ""

    def _unmodelled_instances(self, value: Value) -> list[Obj]:
        classes = self.lib.classes
        return [a for a in value if type(a) is Obj and type(a.cls) is Extern and a.cls.qualname not in classes]

    def _record(self, kind: str, values: tuple, node: ast.AST) -> None:
        frame = self.frame
        frame.effects[(id(node), kind, 0)] = Effect(
            kind, values, frame.module.path, getattr(node, "lineno", 0), frame.module.column(node),
            frame.cls is None and frame.block not in frame.dominators)


def _plain_chain(expr: ast.expr) -> bool:
    """Names and attribute loads only (evaluating them again has no effect of its own), and
    short: a chain is walked once per attribute of it."""
    for _ in range(MAX_CHAIN):
        if not isinstance(expr, ast.Attribute):
            return isinstance(expr, ast.Name)
        expr = expr.value
    return False
