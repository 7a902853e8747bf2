"""Library models: what code outside the workspace does, read from declarative TOML stubs.

The analyser never imports a library; it learns from stub files (schema in
``docs/stubs.md``) which functions and classes exist, their real parameter lists,
what they return, which arguments they call back later, which *effects* a call has
(an opaque ``kind`` plus argument references, interpreted by whoever consumes the
effects — the analyser itself gives them no meaning) and which values they store on
an object for a later call to load.  Stub files are data only: parameter lists are
parsed with :mod:`ast` and defaults read with :func:`ast.literal_eval`.

A broken entry is skipped with a message naming the file and key; the rest loads.
"""
from __future__ import annotations

import ast
import re
from dataclasses import dataclass, field, replace
from typing import Any, Callable, Iterable

try:
    import tomllib
except ImportError:  # Python 3.10
    import tomli as tomllib  # type: ignore[no-redef]

from .values import Record, Value, atoms, const


class StubError(Exception):
    """A stub entry that does not follow the schema; the message names file and key."""


@dataclass(frozen=True)
class Param:
    name: str
    kind: str                 # "pos" | "kwonly" | "varargs" | "varkw"
    default: Value | None     # None: no default


@dataclass(frozen=True)
class Signature:
    params: tuple[Param, ...]

    @staticmethod
    def parse(text: str) -> "Signature":
        try:
            body = ast.parse(f"def f({text}): pass").body
        except SyntaxError as exc:
            raise StubError(f"bad parameter list {text!r}: {exc.msg}") from None
        fn = body[0]
        if len(body) != 1 or not isinstance(fn, ast.FunctionDef) or len(fn.body) != 1 \
                or not isinstance(fn.body[0], ast.Pass):
            raise StubError(f"bad parameter list {text!r}: not a single parameter list")
        args = fn.args
        out: list[Param] = []
        positional = args.posonlyargs + args.args
        defaults = [None] * (len(positional) - len(args.defaults)) + list(args.defaults)
        for arg, default in zip(positional, defaults):
            out.append(Param(arg.arg, "pos", _literal(default)))
        if args.vararg:
            out.append(Param(args.vararg.arg, "varargs", None))
        for arg, default in zip(args.kwonlyargs, args.kw_defaults):
            out.append(Param(arg.arg, "kwonly", _literal(default)))
        if args.kwarg:
            out.append(Param(args.kwarg.arg, "varkw", None))
        return Signature(tuple(out))


def _literal(node: ast.expr | None) -> Value | None:
    if node is None:
        return None
    try:
        return from_data(ast.literal_eval(node))
    except ValueError:
        raise StubError(f"default {ast.unparse(node)!r} is not a literal") from None


def from_data(data: Any) -> Value:
    """A TOML/literal value as an abstract value (tables become records)."""
    if isinstance(data, (str, int, float, bool)) or data is None:
        return const(data)
    if isinstance(data, (list, tuple)):
        from .values import Seq
        return atoms([Seq("tuple", tuple(from_data(x) for x in data))])
    if isinstance(data, dict):
        return atoms([Record("dict", tuple(sorted((str(k), from_data(v)) for k, v in data.items())))])
    raise StubError(f"unsupported value {data!r}")


@dataclass(frozen=True)
class Ref:
    """Where an effect/return/store takes a value from.

    ``how`` is "arg" (a parameter by name; "@return" is the call's result), "overridable"
    (a parameter whose value is only a default the environment may replace), "const"
    (a literal), "format" (a ``str.format`` template over parameters), "load" (a value
    stored earlier on the object in parameter ``on`` under ``key``), "field" (a
    field of the receiver record), "constant" (the library constant a template names) or
    "object" (the library object a template names in another spelling of its dotted path:
    ``data`` is ``(template, separator, shape)``, see :meth:`.calls.CallSemantics.named_object`).

    ``input`` (``(on, key template)``, from ``input = {on = …, key = …}``) says that the
    value *is* a setting supplied from outside the program — the one the object in
    parameter ``on`` holds under ``key`` — so the value carries that origin
    (:class:`~.values.Input`) and a client can put the setting's real value in its place.
    """

    how: str
    data: Any
    on: str | None = None
    input: tuple[str, str] | None = None
    #: With "overridable" (``none_is_unset = true``): ``None`` is no default at all — the
    #: value is unknown until the environment sets it (``declare_parameter('topic')``).
    none_is_unset: bool = False


def _ref(raw: Any, where: str) -> Ref:
    if isinstance(raw, dict) and "input" in raw:
        spec = raw["input"]
        if not (isinstance(spec, dict) and set(spec) == {"on", "key"}
                and all(isinstance(v, str) for v in spec.values())):
            raise StubError(f"{where}: input must be {{on = PARAM, key = TEMPLATE}}; got {spec!r}")
        rest = {k: v for k, v in raw.items() if k != "input"}
        return replace(_ref(rest, where), input=(spec["on"], spec["key"]))
    if isinstance(raw, str):
        return Ref("arg", raw)
    if isinstance(raw, dict) and len(raw) >= 1:
        keys = set(raw)
        if keys == {"arg"} and isinstance(raw["arg"], str):
            return Ref("arg", raw["arg"])
        if keys == {"overridable"} and isinstance(raw["overridable"], str):
            return Ref("overridable", raw["overridable"])
        if keys == {"overridable", "none_is_unset"} and isinstance(raw["overridable"], str) \
                and isinstance(raw["none_is_unset"], bool):
            return Ref("overridable", raw["overridable"], none_is_unset=raw["none_is_unset"])
        if keys == {"const"}:
            return Ref("const", from_data(raw["const"]))
        if keys == {"format"} and isinstance(raw["format"], str):
            return Ref("format", raw["format"])
        if keys == {"load", "on"} and isinstance(raw["load"], str):
            return Ref("load", raw["load"], str(raw["on"]))
        if keys == {"field"} and isinstance(raw["field"], str):
            return Ref("field", raw["field"])
        if keys == {"constant"} and isinstance(raw["constant"], str):
            return Ref("constant", raw["constant"])
        if keys == {"object", "separator", "shape"} and all(isinstance(v, str) for v in raw.values()) \
                and raw["separator"]:
            try:
                re.compile(raw["shape"])
            except re.error as exc:
                raise StubError(f"{where}: shape is not a regular expression: {exc}") from exc
            return Ref("object", (raw["object"], raw["separator"], raw["shape"]))
    raise StubError(f"{where}: expected a parameter name or one of {{arg=…}}, "
                    f"{{overridable=…}}, {{const=…}}, {{format=…}}, {{load=…, on=…}}, "
                    f"{{field=…}}, {{constant=…}}, {{object=…, separator=…, shape=…}}; got {raw!r}")


@dataclass(frozen=True)
class EffectSpec:
    kind: str
    args: tuple[tuple[str, Ref], ...]


@dataclass(frozen=True)
class StoreSpec:
    """What a call keeps on an object: ``value`` under the key template ``key``.  With
    ``each`` (a parameter holding a list of ``(key, value, …)`` tuples), one store per
    entry, whose first item the templates name ``@key`` and second ``@value``
    (``Node.declare_parameters``)."""

    on: str
    key: str          # a format template over parameters
    value: Ref
    each: str | None = None


@dataclass(frozen=True)
class ReturnSpec:
    """``how``: "instance" (new object of class ``data``), "record" (a record of class
    ``data`` with ``fields``), "ref" (the value of a :class:`Ref`), "partial" (the callable
    in parameter ``data`` with the arguments of the parameters named in ``fields`` —
    ``args``: a sequence, ``keywords``: a mapping — bound in front), "enter" (what the
    ``__enter__`` of the argument of parameter ``data`` returns, as ``with`` would call it),
    or "unknown"."""

    how: str
    data: Any = None
    fields: tuple[tuple[str, Ref], ...] = ()


@dataclass(frozen=True)
class FunctionModel:
    qualname: str
    signature: Signature
    returns: ReturnSpec
    effects: tuple[EffectSpec, ...] = ()
    stores: tuple[StoreSpec, ...] = ()
    callbacks: tuple[str, ...] = ()
    #: For callbacks the library calls with arguments the caller gave beside them
    #: (``Thread(target=f, args=(node,))``): ``(callback, args parameter, keywords parameter)``.
    callback_args: tuple[tuple[str, str | None, str | None], ...] = ()
    #: Why a call blocks its thread until something else happens (``None``: it returns
    #: promptly). Opaque to the analyser; rules about callbacks read it.
    blocking: str | None = None
    #: The parameter holding how long a blocking call lasts, in seconds, when it is bounded.
    blocks_for: str | None = None


@dataclass(frozen=True)
class ClassModel:
    qualname: str
    bases: tuple[str, ...]
    methods: dict[str, FunctionModel]
    record: bool = False
    entry: bool = False
    calls_methods: tuple[str, ...] = ()
    #: Methods a workspace class whose base class is unresolved is taken to inherit from
    #: this model, each with the kinds its arguments must have (see :class:`StandIn`).
    stand_in_for_unresolved: dict[str, "StandIn"] = field(default_factory=dict)
    #: Classes the framework constructs (their ``__init__`` applied with no arguments) and
    #: passes, positionally, when it instantiates a user subclass (an rqt plugin's context).
    entry_args: tuple[str, ...] = ()
    #: Names a plugin registration gives this class by (``rqt_gui_py::Plugin`` in a
    #: ``plugin.xml`` ``base_class_type``): the framework behind it builds the classes
    #: registered so, whatever their Python base (see :meth:`LibraryModel.registered_base`).
    registered_as: tuple[str, ...] = ()
    #: Objects of this class are made by code the analysis cannot see and handed over: a
    #: function no analysed code calls, whose parameter is annotated with the class, gets one
    #: object standing for what its caller passes (a node handed to a helper; see
    #: :mod:`.passed_in`) instead of an unknown value.
    passed_in: bool = False


#: Kinds a stand-in method's argument may be required to have: a class (a message type),
#: a function or bound method, a string, a number. A trailing ``?`` lets it be unknown.
ARGUMENT_KINDS = frozenset({"class", "function", "str", "number"})


@dataclass(frozen=True)
class StandIn:
    """A modelled method that a workspace class with an unresolved base (imported from a
    library no stub models) may be calling on itself: only calls that bind to the model's
    parameter list exactly and whose arguments have ``kinds`` are taken to be it (a
    same-named method of some other framework, called with other arguments, is not it)."""

    owner: str                              # the model class that declares it
    kinds: tuple[tuple[str, str], ...]      # (parameter, kind[?])


@dataclass
class LibraryModel:
    functions: dict[str, FunctionModel] = field(default_factory=dict)
    classes: dict[str, ClassModel] = field(default_factory=dict)
    constants: dict[str, Value] = field(default_factory=dict)
    aliases: dict[str, str] = field(default_factory=dict)
    #: Libraries (module prefixes) none of whose classes defines ``__bool__`` or ``__len__``:
    #: every instance of theirs is true (``node or create_node('tree')`` keeps ``node``).
    true_instances: set[str] = field(default_factory=set)
    errors: list[str] = field(default_factory=list)
    #: ``(__module__, __name__)`` of a library class the stubs do not list but whose names
    #: follow a generator's convention (set by the caller that knows the convention);
    #: ``None``: unknown. Code dispatching on these names then takes only its true branch.
    class_identity: Callable[[str], tuple[str, str] | None] = field(
        default=lambda qualname: None, repr=False)
    #: Whether a library class the stubs do not list derives from ``object`` alone (set by the
    #: caller that knows: generated classes), so no type test of another class holds for it.
    closed_class: Callable[[str], bool] = field(default=lambda qualname: False, repr=False)
    _canonical: dict[str, str] = field(default_factory=dict, repr=False)
    _mro: dict[str, list[str]] = field(default_factory=dict, repr=False)
    _stand_ins: dict[str, StandIn] | None = field(default=None, repr=False)

    def instance_is_true(self, cls_qualname: str) -> bool:
        """Whether every instance of the library class ``cls_qualname`` is true."""
        return any(cls_qualname == prefix or cls_qualname.startswith(prefix + ".")
                   for prefix in self.true_instances)

    def canonical(self, qualname: str) -> str:
        """Follow aliases (longest dotted prefix first): ``rclpy.lifecycle.Node`` → ``…LifecycleNode``."""
        known = self._canonical.get(qualname)
        if known is None:
            known = self._canonical[qualname] = self._follow_aliases(qualname)
        return known

    def _follow_aliases(self, qualname: str) -> str:
        for _ in range(8):
            parts = qualname.split(".")
            for cut in range(len(parts), 0, -1):
                head = ".".join(parts[:cut])
                target = self.aliases.get(head)
                if target is not None:
                    qualname = ".".join([target] + parts[cut:])
                    break
            else:
                return qualname
        return qualname

    def knows(self, qualname: str) -> bool:
        """Whether a stub models ``qualname`` (a function, class or constant)."""
        name = self.canonical(qualname)
        return name in self.functions or name in self.classes or name in self.constants

    def ancestors(self, qualname: str) -> list[str] | None:
        """Every class an instance of library class ``qualname`` is an instance of, when the
        list is complete (its modelled bases, or a closed class); ``None`` otherwise."""
        if qualname in self.classes or not self.closed_class(qualname):
            return None
        return [qualname]

    def mro(self, qualname: str) -> list[str]:
        """Library classes from ``qualname`` up its modelled bases (depth-first, no repeats)."""
        known = self._mro.get(qualname)
        if known is None:
            known = self._mro[qualname] = self._library_mro(qualname)
        return known

    def _library_mro(self, qualname: str) -> list[str]:
        out: list[str] = []
        stack = [qualname]
        while stack:
            cur = stack.pop(0)
            if cur in out:
                continue
            out.append(cur)
            model = self.classes.get(cur)
            if model:
                stack[:0] = list(model.bases)
        return out

    def active_roots(self) -> frozenset[str]:
        """Top-level packages whose models have effects or entry classes (``rclpy``, ``tf2_ros``…):
        code that imports none of them, directly or through the workspace, creates nothing."""
        roots = set()
        for name, fn in self.functions.items():
            if fn.effects:
                roots.add(name.split(".")[0])
        for name, cls in self.classes.items():
            if cls.entry or cls.entry_args or any(m.effects for m in cls.methods.values()):
                roots.add(name.split(".")[0])
        roots.update(alias.split(".")[0] for alias, target in self.aliases.items()
                     if target.split(".")[0] in roots)
        return frozenset(roots)

    def stand_in(self, name: str) -> StandIn | None:
        """The model of method ``name`` for workspace classes whose base is unresolved (the
        first declaring class by name: stub files are expected to declare each method once)."""
        if self._stand_ins is None:
            found: dict[str, StandIn] = {}
            for cls_name in sorted(self.classes):
                for method, spec in self.classes[cls_name].stand_in_for_unresolved.items():
                    found.setdefault(method, spec)
            self._stand_ins = found
        return self._stand_ins.get(name)

    def method(self, cls_qualname: str, name: str) -> FunctionModel | None:
        for cls in self.mro(cls_qualname):
            model = self.classes.get(cls)
            if model and name in model.methods:
                return model.methods[name]
        return None

    def class_flag(self, cls_qualname: str, flag: str) -> bool:
        return any(getattr(self.classes.get(c), flag, False) for c in self.mro(cls_qualname))

    def registered_base(self, written: str) -> str | None:
        """The modelled class a registration names by ``written`` (its ``registered_as``), the
        first by name if several claim it."""
        return next((name for name in sorted(self.classes)
                     if written in self.classes[name].registered_as), None)

    def called_methods(self, cls_qualname: str) -> tuple[str, ...]:
        out: list[str] = []
        for cls in self.mro(cls_qualname):
            model = self.classes.get(cls)
            if model:
                out.extend(m for m in model.calls_methods if m not in out)
        return tuple(out)


# -- loading ----------------------------------------------------------------------------
_FUNC_KEYS = {"params", "returns", "effects", "stores", "callbacks", "callback_args", "blocking",
              "blocks_for"}
_CLASS_KEYS = {"bases", "methods", "record", "entry", "calls_methods", "stand_in_for_unresolved",
               "entry_args", "registered_as", "passed_in"}
_TOP_KEYS = {"functions", "classes", "constants", "aliases", "meta", "true_instances"}


def _table(raw: Any, where: str) -> dict:
    if not isinstance(raw, dict):
        raise StubError(f"{where}: expected a table, got {type(raw).__name__}")
    return raw


def _list(raw: Any, where: str) -> list:
    if not isinstance(raw, list):
        raise StubError(f"{where}: expected a list of tables")
    return raw


def _strings(raw: Any, where: str) -> tuple[str, ...]:
    if not isinstance(raw, list) or not all(isinstance(x, str) for x in raw):
        raise StubError(f"{where}: expected a list of strings")
    return tuple(raw)


def _returns(raw: Any, where: str) -> ReturnSpec:
    if raw is None:
        return ReturnSpec("unknown")
    if isinstance(raw, str):
        return ReturnSpec("instance", raw)
    raw = _table(raw, where)
    if "partial" in raw:
        unknown = set(raw) - {"partial", "args", "keywords"}
        if unknown:
            raise StubError(f"{where}: unknown key {sorted(unknown)[0]!r}")
        if not all(isinstance(v, str) for v in raw.values()):
            raise StubError(f"{where}: partial, args and keywords name parameters")
        return ReturnSpec("partial", raw["partial"],
                          tuple(sorted((k, Ref("arg", raw[k])) for k in ("args", "keywords") if k in raw)))
    if "record" in raw:
        unknown = set(raw) - {"record", "fields"}
        if unknown:
            raise StubError(f"{where}: unknown key {sorted(unknown)[0]!r}")
        fields = _table(raw.get("fields", {}), where + ".fields")
        return ReturnSpec("record", str(raw["record"]),
                          tuple(sorted((k, _ref(v, f"{where}.fields.{k}")) for k, v in fields.items())))
    if "enter" in raw:
        if set(raw) != {"enter"} or not isinstance(raw["enter"], str):
            raise StubError(f"{where}: enter names one parameter and nothing else")
        return ReturnSpec("enter", raw["enter"])
    return ReturnSpec("ref", _ref(raw, where))


def _function(qualname: str, raw: Any, where: str) -> FunctionModel:
    raw = _table(raw, where)
    unknown = set(raw) - _FUNC_KEYS
    if unknown:
        raise StubError(f"{where}: unknown key {sorted(unknown)[0]!r}")
    params = raw.get("params", "*args, **kwargs")
    if not isinstance(params, str):
        raise StubError(f"{where}.params: expected a string like \"self, topic, *, qos=10\"")
    try:
        signature = Signature.parse(params)
    except StubError as exc:
        raise StubError(f"{where}.params: {exc}") from None
    effects = []
    for i, eff in enumerate(_list(raw.get("effects", []), where + ".effects")):
        eff = _table(eff, f"{where}.effects[{i}]")
        kind = eff.get("kind")
        if not isinstance(kind, str):
            raise StubError(f"{where}.effects[{i}]: needs kind = \"…\"")
        args = tuple(sorted((k, _ref(v, f"{where}.effects[{i}].{k}"))
                            for k, v in eff.items() if k != "kind"))
        effects.append(EffectSpec(kind, args))
    stores = []
    for i, st in enumerate(_list(raw.get("stores", []), where + ".stores")):
        st = _table(st, f"{where}.stores[{i}]")
        if not {"on", "key", "value"} <= set(st) <= {"on", "key", "value", "each"}:
            raise StubError(f"{where}.stores[{i}]: needs on, key, value (and may have each)")
        stores.append(StoreSpec(str(st["on"]), str(st["key"]),
                                _ref(st["value"], f"{where}.stores[{i}].value"),
                                str(st["each"]) if "each" in st else None))
    blocking = raw.get("blocking")
    if blocking is not None and (not isinstance(blocking, str) or not blocking.strip()):
        raise StubError(f"{where}.blocking: expected a non-empty string saying why the call blocks")
    blocks_for = raw.get("blocks_for")
    if blocks_for is not None:
        if blocking is None:
            raise StubError(f"{where}.blocks_for: only meaningful with blocking = \"…\"")
        if blocks_for not in {p.name for p in signature.params}:
            raise StubError(f"{where}.blocks_for: {blocks_for!r} is not a parameter")
    callbacks = _strings(raw.get("callbacks", []), where + ".callbacks")
    return FunctionModel(qualname, signature, _returns(raw.get("returns"), where + ".returns"),
                         tuple(effects), tuple(stores), callbacks,
                         _callback_args(raw.get("callback_args", {}), callbacks, signature,
                                        where + ".callback_args"),
                         blocking, blocks_for)


def _callback_args(raw: Any, callbacks: tuple[str, ...], signature: Signature,
                   where: str) -> tuple[tuple[str, str | None, str | None], ...]:
    """``callback_args = { target = { args = "args", keywords = "kwargs" } }``: the parameters
    holding the positional sequence and the keyword mapping a callback is called with."""
    params = {p.name for p in signature.params}
    out = []
    for callback, spec in sorted(_table(raw, where).items()):
        spec = _table(spec, f"{where}.{callback}")
        if callback not in callbacks:
            raise StubError(f"{where}.{callback}: not one of callbacks")
        if not spec or set(spec) - {"args", "keywords"}:
            raise StubError(f"{where}.{callback}: expected args = \"param\" and/or keywords = \"param\"")
        for key, name in spec.items():
            if name not in params:
                raise StubError(f"{where}.{callback}.{key}: {name!r} is not a parameter")
        out.append((callback, spec.get("args"), spec.get("keywords")))
    return tuple(out)


def _class(qualname: str, raw: Any, where: str) -> ClassModel:
    raw = _table(raw, where)
    unknown = set(raw) - _CLASS_KEYS
    if unknown:
        raise StubError(f"{where}: unknown key {sorted(unknown)[0]!r}")
    methods = {name: _function(f"{qualname}.{name}", m, f"{where}.methods.{name}")
               for name, m in _table(raw.get("methods", {}), where + ".methods").items()}
    for flag in ("record", "entry", "passed_in"):
        if not isinstance(raw.get(flag, False), bool):
            raise StubError(f"{where}.{flag}: expected true or false")
    return ClassModel(qualname, _strings(raw.get("bases", []), where + ".bases"), methods,
                      raw.get("record", False), raw.get("entry", False),
                      _strings(raw.get("calls_methods", []), where + ".calls_methods"),
                      _stand_ins(qualname, raw.get("stand_in_for_unresolved", {}),
                                 where + ".stand_in_for_unresolved"),
                      _strings(raw.get("entry_args", []), where + ".entry_args"),
                      _strings(raw.get("registered_as", []), where + ".registered_as"),
                      raw.get("passed_in", False))


def _stand_ins(owner: str, raw: Any, where: str) -> dict[str, StandIn]:
    """``{ method = { param = "kind", … }, … }``. A parameter the method lacks is never given,
    so a required kind on it makes no call match (the method may come from a base class in
    another stub file, so this is not checked here)."""
    out = {}
    for method, kinds in _table(raw, where).items():
        kinds = _table(kinds, f"{where}.{method}")
        for param, kind in kinds.items():
            if not isinstance(kind, str) or kind.rstrip("?") not in ARGUMENT_KINDS:
                raise StubError(f"{where}.{method}.{param}: expected one of "
                                f"{', '.join(sorted(ARGUMENT_KINDS))} (optionally with a trailing ?)")
        out[method] = StandIn(owner, tuple(sorted(kinds.items())))
    return out


def _constant(raw: Any, where: str) -> Value:
    try:
        return _constant_value(raw, where)
    except StubError as exc:
        message = str(exc)
        raise StubError(message if message.startswith(where) else f"{where}: {message}") from None


def _constant_value(raw: Any, where: str) -> Value:
    if isinstance(raw, dict) and "record" in raw:
        fields = _table(raw.get("fields", {}), where + ".fields")
        return atoms([Record(str(raw["record"]),
                             tuple(sorted((k, from_data(v)) for k, v in fields.items())))])
    if isinstance(raw, dict) and set(raw) == {"value"}:
        return from_data(raw["value"])
    raise StubError(f"{where}: expected {{ value = … }} or {{ record = …, fields = {{…}} }}")


def load_stub_text(text: str, source: str, model: LibraryModel) -> None:
    """Merge one stub file into ``model``; problems go to ``model.errors`` (file and key named)."""
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        model.errors.append(f"{source}: not valid TOML: {exc}")
        return
    except RecursionError:
        model.errors.append(f"{source}: not loaded: nested too deeply")
        return
    for key in sorted(set(data) - _TOP_KEYS):
        model.errors.append(f"{source}: unknown top-level key {key!r}")
    sections = (("functions", _function, model.functions), ("classes", _class, model.classes),
                ("constants", None, model.constants))
    for section, reader, target in sections:
        raw = data.get(section, {})
        if not isinstance(raw, dict):
            model.errors.append(f"{source}: [{section}] must be a table")
            continue
        for name, entry in raw.items():
            where = f"{source}: {section}.{name!r}"
            try:
                target[name] = reader(name, entry, where) if reader else _constant(entry, where)
            except StubError as exc:
                model.errors.append(str(exc))
            except RecursionError:
                model.errors.append(f"{where}: nested too deeply")
    true_instances = data.get("true_instances", [])
    if isinstance(true_instances, list) and all(isinstance(p, str) for p in true_instances):
        model.true_instances.update(true_instances)
    else:
        model.errors.append(f"{source}: true_instances: expected a list of module names")
    aliases = data.get("aliases", {})
    if isinstance(aliases, dict):
        for name, target in aliases.items():
            if isinstance(target, str):
                model.aliases[name] = target
            else:
                model.errors.append(f"{source}: aliases.{name!r}: expected a string")
    else:
        model.errors.append(f"{source}: [aliases] must be a table")


def load_library(files: Iterable[tuple[str, str]]) -> LibraryModel:
    """Load ``(source name, text)`` pairs in order (later files override earlier entries)."""
    model = LibraryModel()
    for source, text in files:
        load_stub_text(text, source, model)
    return model
