"""The values of the constants the workspace's interface files define.

A ``.msg`` line ``string DEPTH_TOPIC = 'core/depth'`` (rosidl's ``type NAME=value``) makes
``DEPTH_TOPIC`` a class attribute of the Python class rosidl generates, so code can name its
topics in one message file (``Topics.DEPTH_TOPIC``) for every node. The analysis cannot
import the generated class; it reads the value here, as rosidl's front end would, under the
class attribute's qualified name (``pkg.msg.Topics.DEPTH_TOPIC``; a service's or action's
parts as ``pkg.srv.Name.Request.X`` and ``pkg.srv.Name_Request.X``).

A value this reading is not sure of — a number that does not parse, an unquoted string
holding a ``#`` (a comment or text?) — is left out: the attribute stays unknown rather
than wrong.
"""
from __future__ import annotations

import re
from typing import Iterable, Union

from .catalogue import InterfaceFile
from .definitions import PARTS, InterfaceError, split_parts

ConstantValue = Union[str, int, float, bool]

#: ``type NAME = value``: a primitive type (optionally a bounded string) and an upper-case name.
_CONSTANT = re.compile(r"^(?P<type>[a-z][a-z0-9]*)(?:<=\d+)?\s+(?P<name>[A-Za-z][A-Za-z0-9_]*)\s*=\s*(?P<value>.*)$")
_INTEGERS = frozenset({"byte", "char", "int8", "uint8", "int16", "uint16", "int32", "uint32",
                       "int64", "uint64"})
_FLOATS = frozenset({"float32", "float64"})
_STRINGS = frozenset({"string", "wstring"})


def interface_constants(files: Iterable[InterfaceFile]) -> dict[str, ConstantValue]:
    """Qualified class-attribute name -> value, for every constant of ``files`` read for sure
    (later files win, as in the catalogue)."""
    out: dict[str, ConstantValue] = {}
    for file in files:
        if file.text is None:
            continue
        try:
            chunks = split_parts(file.text, file.package, file.kind, file.name)
        except InterfaceError:  # the catalogue reports it
            continue
        for suffix, chunk in zip(PARTS[file.kind], chunks):
            for owner in _owners(file.package, file.kind, file.name, suffix):
                out.update((f"{owner}.{name}", value) for name, value in _constants(chunk))
    return out


def _owners(package: str, kind: str, name: str, suffix: str) -> list[str]:
    """The Python names of the generated class holding a part's constants."""
    if not suffix:
        return [f"{package}.{kind}.{name}"]
    return [f"{package}.{kind}.{name}.{suffix[1:]}", f"{package}.{kind}.{name}{suffix}"]


def _constants(lines: list[str]) -> Iterable[tuple[str, ConstantValue]]:
    for raw in lines:
        match = _CONSTANT.match(raw.strip())
        if match is None:
            continue
        value = _value(match.group("type"), match.group("value").strip())
        if value is not None:
            yield match.group("name"), value


def _value(type_name: str, text: str) -> ConstantValue | None:
    """The constant as rosidl stores it, or ``None`` when not sure."""
    if type_name in _STRINGS:
        return _string(text)
    text = text.split("#", 1)[0].strip()
    try:
        if type_name == "bool":
            return {"true": True, "1": True, "false": False, "0": False}.get(text.lower())
        if type_name in _INTEGERS:
            return int(text)
        if type_name in _FLOATS:
            return float(text)
    except ValueError:
        return None
    return None


def _string(text: str) -> str | None:
    """A string constant's text: between its quotes (a comment may follow), else the rest of
    the line when it holds no ``#``."""
    if text[:1] in ("'", '"'):
        quote = text[0]
        end = text.find(quote, 1)
        while end > 0 and text[end - 1] == "\\":
            end = text.find(quote, end + 1)
        if end < 0:
            return None
        rest = text[end + 1:].strip()
        if rest and not rest.startswith("#"):
            return None
        return text[1:end].replace("\\" + quote, quote)
    if "#" in text:
        return None
    return text
