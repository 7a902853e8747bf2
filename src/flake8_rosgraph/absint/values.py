"""The value lattice: immutable abstract values for Python expressions.

An abstract :class:`Value` is either ⊤ ("anything") or a finite set of *atoms*, each
atom one concrete possibility: a constant, a heap object named by its allocation site, a
function, a class, an external (library) symbol, a tuple/list/dict shape.  The empty set
is ⊥ (unreachable / not yet known).

⊤ comes in two kinds.  :data:`TOP` is an unknown that remembers, as *hints*, the
constants it was joined with: ``self.get_parameter('t').value if c else '/scan'`` is
"``'/scan'`` or something else", so the graph can still name ``/scan`` — as a name that
is known only partly, since the unknown part may be anything.  :data:`SATURATED` is ⊤
past the bounds (too many atoms or hints, a widened loop value, an unknown joined with
objects): it keeps nothing and absorbs every join, so it is the top of the lattice.
A hinted ⊤ *is* ⊤ to everything but the graph builder (``is_top``, no atoms, no
constants): no branch is decided and no value computed from a hint.

A value may also carry an *origin*: it **is** one input the program receives from outside
(an :class:`Input`: a setting an object holds under a key, supplied when the program runs —
the atoms, if any, are only its default), or a string joined from such inputs and known
text (:class:`Joined`: ``ns + '/scan'``, ``f'/{ns}/scan'``).  Passing the value on keeps
the origin; joining it with a value of the same origin keeps it; anything else computed
from it, or joined with anything else, is a plain value again.  A client that knows the
inputs' values for one run (a deployment file) can rebuild the value from them.  The
origin decides nothing in the analysis.

Atom sets and hint sets are bounded by :data:`MAX_ATOMS`; past the bound a value
saturates, which makes every ascending chain finite — so joining is already a
widening, and loops reach a fixpoint.

Atoms are frozen dataclasses so values hash, compare and can key analysis contexts.
Nothing here knows about ROS.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Iterable, Iterator, Union

#: Bound on the number of atoms a value may hold before it widens to ⊤.
MAX_ATOMS = 12
#: Bound for values holding heap objects, functions and classes: those are finitely many
#: (allocation sites × bounded contexts), so a larger set still keeps chains finite — and
#: a launch description gets its twenty ``add_action`` calls.
MAX_OBJECTS = 64
#: Bound on nesting of containers (a tuple in a list in a dict …) before ⊤.
MAX_DEPTH = 4
#: Bound on records directly inside records (see :attr:`Record.nesting`) before ⊤.
MAX_RECORD_NESTING = 8

ConstType = Union[str, int, float, bool, None, bytes, complex]


_NAN = float("nan")


@dataclass(frozen=True, eq=False)
class Const:
    """A Python literal. ``kind`` keeps ``1``, ``1.0`` and ``True`` apart (they hash alike)."""

    kind: str
    value: ConstType

    def __eq__(self, other: object) -> bool:
        # Identity first, so the one canonical NaN equals itself on every Python version
        # (3.13's generated __eq__ compares fields with == only).
        return isinstance(other, Const) and self.kind == other.kind and (
            self.value is other.value or self.value == other.value)

    def __hash__(self) -> int:
        return hash((self.kind, self.value))

    @staticmethod
    def of(value: ConstType) -> "Const":
        if type(value) is float:
            # -0.0 == 0.0 and NaN != NaN would make sets of constants depend on the order
            # values arrive in: one canonical zero, one canonical NaN.
            if value != value:
                value = _NAN
            elif value == 0.0:
                value = 0.0
        return Const(type(value).__name__, value)


@dataclass(frozen=True)
class Obj:
    """A heap object: instances allocated at one site share one abstract object."""

    site: str   # allocation site key, e.g. "pkg/mod.py:12:8"
    cls: "Atom"  # ClassAtom or Extern (library class)


@dataclass(frozen=True)
class FuncAtom:
    """A user function or lambda (``fid`` indexes the program's function table)."""

    fid: int


@dataclass(frozen=True)
class BoundMethod:
    """A user function bound to a receiver (``self`` or a class for classmethods)."""

    receiver: "Atom"
    fid: int


@dataclass(frozen=True)
class ClassAtom:
    """A user class (``cid`` indexes the program's class table)."""

    cid: int


@dataclass(frozen=True)
class ModuleAtom:
    """A module of the analysed workspace."""

    name: str


@dataclass(frozen=True)
class Extern:
    """A symbol outside the workspace, by qualified name (``rclpy.node.Node``, ``std_msgs.msg.String``)."""

    qualname: str


@dataclass(frozen=True)
class ExternBound:
    """A library method bound to a receiver: ``qualname`` is the method's ``Class.method``."""

    receiver: "Atom"
    qualname: str


@dataclass(frozen=True)
class SuperAtom:
    """``super()`` inside class ``cid`` for receiver ``receiver``."""

    cid: int
    receiver: "Atom"


@dataclass(frozen=True)
class Seq:
    """A tuple or list of known length."""

    kind: str  # "tuple" | "list"
    items: tuple["Value", ...]
    depth: int = field(init=False, compare=False, repr=False, default=0)

    def __post_init__(self) -> None:
        object.__setattr__(self, "depth", 1 + max((v.depth for v in self.items), default=0))


@dataclass(frozen=True)
class Coll:
    """A collection of unknown length whose elements are ``elem`` (comprehensions, ``list.append``)."""

    kind: str
    elem: "Value"
    depth: int = field(init=False, compare=False, repr=False, default=0)

    def __post_init__(self) -> None:
        object.__setattr__(self, "depth", 1 + self.elem.depth)


@dataclass(frozen=True)
class DictAtom:
    """A dict literal with (key, value) pairs."""

    items: tuple[tuple["Value", "Value"], ...]
    depth: int = field(init=False, compare=False, repr=False, default=0)

    def __post_init__(self) -> None:
        object.__setattr__(self, "depth", 1 + max(
            (max(k.depth, v.depth) for k, v in self.items), default=0))


@dataclass(frozen=True)
class Partial:
    """A callable with arguments bound in front (``functools.partial(func, *args, **kw)``):
    calling it, or a library calling it back, passes ``args`` before the caller's own
    positional arguments and ``kw`` under the caller's keywords, so a callback keeps the
    values it was registered with. ``star``: more arguments were bound than are known
    (``partial(f, *names)``), so no parameter's position is known past ``args``."""

    func: "Atom"                               # any callable atom, a Partial included
    args: tuple["Value", ...]
    kw: tuple[tuple[str, "Value"], ...]
    star: bool = False
    depth: int = field(init=False, compare=False, repr=False, default=0)

    def __post_init__(self) -> None:
        object.__setattr__(self, "depth", 1 + max(
            [v.depth for v in self.args] + [v.depth for _, v in self.kw] + [getattr(self.func, "depth", 0)],
            default=0))


@dataclass(frozen=True)
class Record:
    """A library value described field by field by a stub (e.g. a QoS profile)."""

    qualname: str
    fields: tuple[tuple[str, "Value"], ...]
    #: The containers' nesting inside its fields (a record is no container level itself: a
    #: launch description's include of a joined path is records in records).
    depth: int = field(init=False, compare=False, repr=False, default=0)
    #: Records directly inside records, this one included: bounded by
    #: :data:`MAX_RECORD_NESTING`, so that a record built from the value it replaces
    #: (``self.dir = os.path.join(root, self.dir)`` re-run as the field grows), whose text
    #: doubles with each level, stops growing.
    nesting: int = field(init=False, compare=False, repr=False, default=1)

    def __post_init__(self) -> None:
        object.__setattr__(self, "depth", max((v.depth for _, v in self.fields), default=0))
        object.__setattr__(self, "nesting", 1 + max(
            (a.nesting for _, v in self.fields if v.atoms for a in v.atoms if type(a) is Record), default=0))

    def field(self, name: str) -> "Value | None":
        for key, val in self.fields:
            if key == name:
                return val
        return None


@dataclass(frozen=True)
class Input:
    """The setting ``key`` of the heap object allocated at ``holder``, supplied from outside
    the program (its stored value, if any, is only the default)."""

    holder: str
    key: str


@dataclass(frozen=True)
class Slot:
    """An outside input inside joined text, with the one string it defaults to (if known)."""

    input: Input
    default: str | None


@dataclass(frozen=True)
class Joined:
    """A string joined, in order, from constant text and outside inputs (``ns + '/scan'``
    where ``ns`` is an :class:`Input`): a client that knows the inputs' values (or takes
    their defaults) can rebuild it."""

    parts: tuple[Union[str, Slot], ...]


#: Where a value comes from outside the program: one input, or text joined from inputs.
Origin = Union[Input, Joined]


Atom = Union[Const, Obj, FuncAtom, BoundMethod, ClassAtom, ModuleAtom, Extern, ExternBound,
             SuperAtom, Seq, Coll, DictAtom, Partial, Record]


class Value:
    """An element of the value lattice; construct with :func:`atoms`, :data:`TOP`, :data:`BOTTOM`."""

    __slots__ = ("atoms", "soft", "hints", "origin", "_hash", "_repr", "_ordered")

    def __init__(self, items: frozenset | None, soft: bool = False,
                 hints: frozenset | None = frozenset(), origin: Origin | None = None) -> None:
        # ``None`` means ⊤.  ``soft``: these are defaults the environment may override
        # (a command-line option, a ROS parameter): good for naming what runs by
        # default, never for deciding a branch.  ⊤ is never soft.  ``hints``: for ⊤,
        # the constants it may also be (``None``: saturated, hints given up); empty
        # for a known value.  ``origin``: the outside input this value is (⊥ is no input).
        self.atoms = items
        self.soft = soft and items is not None
        self.hints = hints if items is None else frozenset()
        self.origin = origin if items is None or items else None
        self._hash = hash((items, self.soft, self.hints, self.origin))
        self._repr: str | None = None
        self._ordered: tuple[Atom, ...] | None = None

    @property
    def depth(self) -> int:
        """Container nesting of the deepest atom (0 for ⊤ and scalars)."""
        return max((getattr(a, "depth", 0) for a in self.atoms), default=0) if self.atoms else 0

    @property
    def is_top(self) -> bool:
        return self.atoms is None

    @property
    def is_bottom(self) -> bool:
        return self.atoms is not None and not self.atoms

    @property
    def is_saturated(self) -> bool:
        """⊤ that keeps no hints, is no input, and absorbs every join (the lattice's greatest
        element)."""
        return self.hints is None and self.origin is None

    def hinted(self) -> list[ConstType]:
        """The constants a ⊤ is known to include beside its unknown part (sorted by repr)."""
        return [h.value for h in sorted(self.hints, key=repr)] if self.hints else []

    def __iter__(self) -> Iterator[Atom]:
        """The atoms in the order of their text, never the set's: what the analysis does for
        each (calls, schedules, instances) must not follow the hash seed, or neither would
        which contexts a function gets first, nor its output (kept per value, as it is immutable)."""
        if self.atoms is None:
            return iter(())
        if len(self.atoms) < 2:
            return iter(self.atoms)
        if self._ordered is None:
            self._ordered = tuple(sorted(self.atoms, key=repr))
        return iter(self._ordered)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Value) and self.atoms == other.atoms and \
            self.soft == other.soft and self.hints == other.hints and self.origin == other.origin

    def __hash__(self) -> int:
        return self._hash

    def __repr__(self) -> str:
        # Kept once computed: values are immutable, and the engine orders atoms, tasks and
        # effects by this text (nested values are rendered again for every container).
        if self._repr is None:
            self._repr = self._render()
        return self._repr

    def _render(self) -> str:
        origin = "@" + _origin_text(self.origin) if self.origin is not None else ""
        if self.atoms is None:
            if self.hints is None:
                return "⊤*" + origin
            return "⊤" + ("∪{" + ", ".join(sorted(map(repr, self.hints))) + "}" if self.hints else "") \
                + origin
        text = "{" + ", ".join(sorted(map(repr, self.atoms))) + "}"
        return ("~" + text if self.soft else text) + origin

    # -- lattice operations ------------------------------------------------
    def join(self, other: "Value") -> "Value":
        if other.atoms is not None and not other.atoms:
            return self   # ⊥ is the identity (and is no input)
        if self.atoms is not None and not self.atoms:
            return other
        origin = self.origin if self.origin == other.origin else None
        if self.atoms is None or other.atoms is None:
            return _unknown_with(self._hint_part(), other._hint_part(), origin)
        soft = self.soft or other.soft
        if other.atoms <= self.atoms and soft == self.soft and origin == self.origin:
            return self
        if self.atoms <= other.atoms and soft == other.soft and origin == other.origin:
            return other
        return _bounded(self.atoms | other.atoms, soft, origin)

    def _hint_part(self) -> frozenset | None:
        """What this value adds to the hints of a ⊤ it is joined with: its constants
        (``None`` when it holds anything else, which saturates the join)."""
        if self.atoms is None:
            return self.hints
        return self.atoms if all(type(a) is Const for a in self.atoms) else None

    def leq(self, other: "Value") -> bool:
        if self.atoms is not None and not self.atoms:
            return True
        if other.origin is not None and other.origin != self.origin:
            return False
        if other.atoms is None:
            if other.hints is None:
                return True
            part = self._hint_part()
            return part is not None and part <= other.hints
        if self.atoms is None:
            return False
        return self.atoms <= other.atoms and (other.soft or not self.soft)

    def widen(self, other: "Value") -> "Value":
        """Widening: any growth at a loop head jumps straight to the saturated ⊤."""
        joined = self.join(other)
        return self if joined == self else SATURATED

    # -- views -----------------------------------------------------------------
    def consts(self) -> list[ConstType] | None:
        """The constants, if every atom is a constant; else ``None``."""
        if self.atoms is None:
            return None
        out = []
        for atom in self.atoms:
            if not isinstance(atom, Const):
                return None
            out.append(atom.value)
        return out

    def strings(self) -> list[str] | None:
        vals = self.consts()
        if vals is None or not all(isinstance(v, str) for v in vals):
            return None
        return sorted(vals)


_CONTAINERS = (Seq, Coll, DictAtom, Partial)
#: ⊤: anything; joined with constants it keeps them as hints.
TOP = Value(None)
#: ⊤ past the bounds: keeps nothing, absorbs every join.
SATURATED = Value(None, hints=None)
BOTTOM = Value(frozenset())
#: Either boolean: the value of a test the analysis cannot decide.
BOOLS = Value(frozenset((Const("bool", True), Const("bool", False))))


def _origin_text(origin: Origin) -> str:
    if isinstance(origin, Input):
        return f"{origin.holder}:{origin.key}"
    return "+".join(repr(p) if isinstance(p, str) else f"{_origin_text(p.input)}={p.default!r}"
                    for p in origin.parts)


def _bounded(items: frozenset, soft: bool = False, origin: Origin | None = None) -> Value:
    if len(items) > MAX_ATOMS and (
            len(items) > MAX_OBJECTS or sum(type(a) is Const for a in items) > MAX_ATOMS):
        return _unknown_with(None, None, origin)
    return Value(items, soft, origin=origin)


def _unknown_with(hints: frozenset | None, more: frozenset | None,
                  origin: Origin | None = None) -> Value:
    """⊤ with the union of two hint sets (saturated when either is, or past the bound)."""
    if hints is None or more is None:
        return SATURATED if origin is None else Value(None, hints=None, origin=origin)
    union = hints | more
    if len(union) > MAX_ATOMS:
        return SATURATED if origin is None else Value(None, hints=None, origin=origin)
    if origin is not None:
        return Value(None, hints=union, origin=origin)
    return Value(None, hints=union) if union else TOP


def atoms(items: Iterable[Atom], soft: bool = False) -> Value:
    """The value holding exactly ``items`` (saturated ⊤ past the bounds)."""
    items = frozenset(items)
    for a in items:
        if type(a) in _CONTAINERS and a.depth > MAX_DEPTH or type(a) is Record and a.nesting > MAX_RECORD_NESTING:
            return SATURATED
    return _bounded(items, soft)


def from_input(value: Value, origin: Origin) -> Value:
    """``value`` as coming from outside as ``origin`` (⊥, no value yet, stays ⊥)."""
    if value.is_bottom or value.origin == origin:
        return value
    return Value(value.atoms, value.soft, value.hints, origin)


def _text_parts(value: Value) -> tuple[Union[str, Slot], ...] | None:
    """``value`` as text parts: the inputs it comes from, or its one known string (``None``
    when it is neither, e.g. a default that is not labelled with what overrides it)."""
    if isinstance(value.origin, Input):
        strings = value.strings()
        return (Slot(value.origin, strings[0] if strings and len(strings) == 1 else None),)
    if isinstance(value.origin, Joined):
        return value.origin.parts
    strings = value.strings()
    if strings is not None and len(strings) == 1 and not value.soft:
        return (strings[0],)
    return None


def joined(result: Value, pieces: list[Value]) -> Value:
    """``result``, the concatenation of the strings ``pieces``, with the inputs it is built
    from when every piece is an input or known text and one is known text (so that it is
    surely a string concatenation): ``ns + '/scan'``, ``f'{ns}/scan'``."""
    if not any(p.origin is not None for p in pieces):
        return result
    parts: list[Union[str, Slot]] = []
    texts = 0
    for piece in pieces:
        found = _text_parts(piece)
        if found is None:
            return result
        texts += isinstance(piece.origin, Joined) or piece.origin is None
        for part in found:
            if isinstance(part, str) and parts and isinstance(parts[-1], str):
                parts[-1] += part
            elif part != "":
                parts.append(part)
    if not texts:
        return result
    return from_input(result, Joined(tuple(parts)))


def soften(value: Value) -> Value:
    """The same possibilities, marked as overridable defaults."""
    return value if value.is_top or value.soft else Value(value.atoms, True)


def wrapped(atom: Atom) -> Atom:
    """The callable that ``atom`` calls in the end: through partials, else ``atom`` itself."""
    while isinstance(atom, Partial):
        atom = atom.func
    return atom


def const(value: ConstType) -> Value:
    # Shared per constant (values are immutable): the engine builds the same few constants
    # (None, literals of the source) again on every run of every task.
    key = (type(value), value)
    try:
        return _CONSTS[key]
    except KeyError:
        made = Value(frozenset((Const.of(value),)))
        if len(_CONSTS) < _MAX_SHARED_CONSTS:
            _CONSTS[key] = made
        return made
    except TypeError:  # unhashable: never shared
        return Value(frozenset((Const.of(value),)))


#: Bound on :data:`_CONSTS`, so that a long-lived process (a language server) stays bounded.
_MAX_SHARED_CONSTS = 100_000
_CONSTS: dict[tuple[type, ConstType], Value] = {}


def join_all(values: Iterable[Value]) -> Value:
    out = BOTTOM
    for v in values:
        out = out.join(v)
        if out.is_saturated:
            return out
    return out
