"""Parsing ``.msg`` / ``.srv`` / ``.action`` text into message definitions.

The grammar is rosidl_adapter's (the ``.msg`` front end every ROS 2 build uses): one field
per line, ``type name [default]`` or a constant ``type NAME=value``; ``#`` starts a comment;
types are primitives, ``pkg/Type`` or a bare ``Type`` of the same package (``Header`` alone
means ``std_msgs/Header``), optionally bounded strings (``string<=N``) and arrays (``T[]``,
``T[N]``, ``T[<=N]``). A service is a request and a response separated by ``---``; an action
a goal, a result and a feedback. Each part becomes a :class:`MessageDef` keyed like
``pkg/srv/Name_Request``.
"""
from __future__ import annotations

import re
from dataclasses import dataclass

#: ``.msg`` primitive types as rclpy's generated classes store them (``byte`` is an octet,
#: ``char`` an unsigned 8-bit integer: rosidl_adapter's MSG_TYPE_TO_IDL).
PRIMITIVES = frozenset({
    "bool", "byte", "char", "float32", "float64", "int8", "uint8", "int16", "uint16",
    "int32", "uint32", "int64", "uint64", "string", "wstring"})

#: The parts of each interface kind, in file order.
PARTS: dict[str, tuple[str, ...]] = {
    "msg": ("",), "srv": ("_Request", "_Response"), "action": ("_Goal", "_Result", "_Feedback")}

_NAME = re.compile(r"^[A-Za-z][A-Za-z0-9_]*$")
_TYPE = re.compile(
    r"^(?:(?P<pkg>[A-Za-z][\w]*)/)?(?P<base>[A-Za-z][\w]*)(?:<=(?P<strbound>\d+))?"
    r"(?P<array>\[(?P<bounded><=)?(?P<size>\d+)?\])?$")


class InterfaceError(ValueError):
    """A line that is not a field or constant definition."""


@dataclass(frozen=True)
class FieldType:
    """A field's type: ``base`` is a primitive or a message key (``std_msgs/msg/Header``);
    ``array`` is ``None``, ``"fixed"``, ``"bounded"`` or ``"unbounded"`` with ``size`` its
    length or bound; ``string_bound`` the maximum length of a bounded string."""

    base: str
    array: str | None = None
    size: int | None = None
    string_bound: int | None = None

    @property
    def is_message(self) -> bool:
        return self.base not in PRIMITIVES

    def element(self) -> "FieldType":
        """The type of one element of an array field (the field's own type otherwise)."""
        return FieldType(self.base, None, None, self.string_bound)

    def spelled(self) -> str:
        """The type as a ``.msg`` file writes it, fully qualified (``builtin_interfaces/Time[<=2]``)."""
        text = self.base.replace("/msg/", "/")
        if self.string_bound is not None:
            text += f"<={self.string_bound}"
        if self.array == "fixed":
            text += f"[{self.size}]"
        elif self.array == "bounded":
            text += f"[<={self.size}]"
        elif self.array == "unbounded":
            text += "[]"
        return text


@dataclass(frozen=True)
class Field:
    name: str
    type: FieldType


@dataclass(frozen=True)
class MessageDef:
    """One message structure (a ``.msg`` file, or one part of a service or action)."""

    key: str                        # "std_msgs/msg/Header", "std_srvs/srv/SetBool_Request"
    fields: tuple[Field, ...]
    constants: tuple[str, ...]      # constant names (class attributes, not fields)

    def field(self, name: str) -> Field | None:
        for item in self.fields:
            if item.name == name:
                return item
        return None

    def lines(self) -> list[str]:
        """The definition as canonical ``.msg`` lines (qualified types, no comments or
        defaults): what ``standard.json`` stores and :func:`parse_message` reads back."""
        out = [f"{f.type.spelled()} {f.name}" for f in self.fields]
        out.extend(f"constant {name}" for name in self.constants)
        return out


def parse_type(text: str, package: str) -> FieldType:
    """A type as written in a ``.msg`` file of ``package`` (bare message types are that package's)."""
    match = _TYPE.match(text)
    if match is None:
        raise InterfaceError(f"bad type {text!r}")
    pkg, base = match.group("pkg"), match.group("base")
    if pkg is None and base not in PRIMITIVES:
        pkg = "std_msgs" if base == "Header" else package
    if pkg is not None:
        base = f"{pkg}/msg/{base}"
    strbound = match.group("strbound")
    if strbound is not None and base not in ("string", "wstring"):
        raise InterfaceError(f"only strings have a length bound: {text!r}")
    array = size = None
    if match.group("array"):
        size_text = match.group("size")
        if match.group("bounded"):
            if size_text is None:
                raise InterfaceError(f"bounded array without a bound: {text!r}")
            array = "bounded"
        else:
            array = "fixed" if size_text is not None else "unbounded"
        size = int(size_text) if size_text is not None else None
    return FieldType(base, array, size, int(strbound) if strbound is not None else None)


def parse_message(text: str, key: str) -> MessageDef:
    """One message structure from its ``.msg`` text; ``key`` names it (``pkg/msg/Name``)."""
    package = key.split("/", 1)[0]
    fields: list[Field] = []
    constants: list[str] = []
    for number, raw in enumerate(text.splitlines(), 1):
        line = raw.strip()
        if not line or line.startswith("#"):
            continue
        type_text, _, rest = line.replace("\t", " ").partition(" ")
        rest = rest.strip()
        if type_text == "constant":  # the canonical form of a constant, as lines() writes it
            constants.append(rest)
            continue
        try:
            field_type = parse_type(type_text, package)
        except InterfaceError as exc:
            raise InterfaceError(f"{key} line {number}: {exc}") from None
        name_part = re.split(r"[\s=#]", rest, maxsplit=1)[0]
        if not _NAME.match(name_part):
            raise InterfaceError(f"{key} line {number}: bad field name {name_part!r}")
        if rest[len(name_part):].lstrip().startswith("="):
            constants.append(name_part)
        else:
            fields.append(Field(name_part, field_type))
    return MessageDef(key, tuple(fields), tuple(constants))


def parse_interface(text: str, package: str, kind: str, name: str) -> list[MessageDef]:
    """Every structure one interface file defines: one for a ``.msg``, two for a ``.srv``, three
    for an ``.action`` (a missing part is empty)."""
    return [parse_message("\n".join(chunk), f"{package}/{kind}/{name}{suffix}")
            for chunk, suffix in zip(split_parts(text, package, kind, name), PARTS[kind])]


def split_parts(text: str, package: str, kind: str, name: str) -> list[list[str]]:
    """The lines of each part of an interface file, in :data:`PARTS` order (``---`` separates
    a request from its response; a missing part is empty)."""
    suffixes = PARTS[kind]
    chunks: list[list[str]] = [[]]
    for line in text.splitlines():
        if line.strip() == "---":
            chunks.append([])
        else:
            chunks[-1].append(line)
    if len(chunks) > len(suffixes):
        raise InterfaceError(f"{package}/{kind}/{name}: more than {len(suffixes)} parts")
    return chunks + [[] for _ in range(len(suffixes) - len(chunks))]
