"""A small YAML reader with line numbers, for YAML launch files and ROS parameter files.

The project may not depend on PyYAML, and findings need lines anyway, which
PyYAML's plain ``safe_load`` does not keep.  This reads the subset that
launch files and ``ros__parameters`` files use: block mappings and sequences
(including ``- key: value`` items and sequences at their key's indentation),
flow ``[…]``/``{…}`` collections (also across lines), single/double-quoted
and plain scalars, ``|``/``>`` block scalars, comments, ``---``, anchors,
aliases and ``<<`` merges.  Scalars are typed like YAML 1.2's core schema
(the way rcl's parameter parser reads them).  Anything else is a
:class:`YamlError` with a line, never a wrong tree.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Any


#: Deepest nesting of collections read (real launch and parameter files nest a few levels).
MAX_DEPTH = 100
#: Most nodes a document may hold once its aliases are expanded (a "billion laughs" stops here).
MAX_NODES = 1_000_000


class YamlError(Exception):
    def __init__(self, line: int, message: str) -> None:
        super().__init__(f"line {line}: {message}")
        self.line = line


@dataclass
class YNode:
    """A value with the 1-based line and column where it starts.

    ``value`` is a ``dict[str, YNode]``, a ``list[YNode]`` or a scalar;
    ``key_lines`` gives, for a mapping, the line of each key.
    """

    value: Any
    line: int
    column: int = 1
    key_lines: dict[str, int] = field(default_factory=dict)
    #: Nodes in this value with every alias expanded (what :meth:`plain` would build).
    size: int = 1

    def plain(self) -> Any:
        """The value with positions dropped, as ``yaml.safe_load`` would return it."""
        if isinstance(self.value, dict):
            return {k: v.plain() for k, v in self.value.items()}
        if isinstance(self.value, list):
            return [v.plain() for v in self.value]
        return self.value


_INT = re.compile(r"^[-+]?[0-9]+$")
_BASED_INT = re.compile(r"^0x[0-9a-fA-F]+$|^0o[0-7]+$")
_FLOAT = re.compile(r"^[-+]?(\.[0-9]+|[0-9]+(\.[0-9]*)?)([eE][-+]?[0-9]+)?$")
_SPECIAL_FLOATS = {".inf": float("inf"), "+.inf": float("inf"), "-.inf": float("-inf"),
                   ".nan": float("nan")}


def scalar(text: str) -> Any:
    """Type a plain (unquoted) scalar."""
    if text in ("", "~", "null", "Null", "NULL"):
        return None
    if text in ("true", "True", "TRUE"):
        return True
    if text in ("false", "False", "FALSE"):
        return False
    if _INT.match(text):
        return int(text)
    if _BASED_INT.match(text):
        return int(text, 0)
    if _FLOAT.match(text) and any(c.isdigit() for c in text):
        return float(text)
    if text.lower() in _SPECIAL_FLOATS:
        return _SPECIAL_FLOATS[text.lower()]
    return text


def _strip_comment(text: str) -> str:
    quote = ""
    for i, char in enumerate(text):
        if quote:
            if char == quote:
                quote = ""
        elif char in "'\"" and (i == 0 or text[i - 1] in " \t[{,:-"):
            quote = char
        elif char == "#" and (i == 0 or text[i - 1] in " \t"):
            return text[:i].rstrip()
    return text.rstrip()


@dataclass
class _Line:
    number: int
    indent: int
    text: str  # without indentation and comment


class _Reader:
    def __init__(self, source: str) -> None:
        self.raw = source.splitlines()
        self.anchors: dict[str, YNode] = {}
        self.lines: list[_Line] = []
        self.index = 0
        self.depth = 0
        for number, raw in enumerate(self.raw, 1):
            if "\t" in raw[:len(raw) - len(raw.lstrip())]:
                raise YamlError(number, "tab in indentation")
            body = _strip_comment(raw)
            stripped = body.lstrip(" ")
            if not stripped or stripped.startswith("%") or stripped in ("---", "..."):
                continue
            if stripped.startswith("--- "):
                stripped = stripped[4:].lstrip()
            self.lines.append(_Line(number, len(body) - len(stripped), stripped))

    # -- blocks ----------------------------------------------------------------------------------
    def document(self) -> YNode:
        if not self.lines:
            return YNode(None, 1)
        node = self.block(self.lines[0].indent)
        if self.index < len(self.lines):
            line = self.lines[self.index]
            raise YamlError(line.number, f"unexpected content {line.text[:30]!r}")
        return node

    def block(self, indent: int) -> YNode:
        line = self.lines[self.index]
        if self.depth >= MAX_DEPTH:
            raise YamlError(line.number, f"collections nested deeper than {MAX_DEPTH}")
        self.depth += 1
        try:
            if line.text == "-" or line.text.startswith("- "):
                return self.sequence(indent)
            if _split_key(line.text) is not None:
                return self.mapping(indent)
            self.index += 1
            return self.inline(line.text, line, line.indent)
        finally:
            self.depth -= 1

    def sequence(self, indent: int) -> YNode:
        first = self.lines[self.index]
        items: list[YNode] = []
        while self.index < len(self.lines):
            line = self.lines[self.index]
            if line.indent != indent or not (line.text == "-" or line.text.startswith("- ")):
                if line.indent > indent:
                    raise YamlError(line.number, "bad indentation")
                break
            rest = line.text[1:].lstrip(" ")
            if not rest:
                self.index += 1
                items.append(self.child(indent, line))
                continue
            # "- key: value" or "- - x": the item is a block that starts inside this line.
            offset = len(line.text) - len(rest)
            self.lines[self.index] = _Line(line.number, indent + offset, rest)
            items.append(self.block(indent + offset))
        return sized(YNode(items, first.number, first.indent + 1))

    def mapping(self, indent: int) -> YNode:
        first = self.lines[self.index]
        out: dict[str, YNode] = {}
        keys: dict[str, int] = {}
        while self.index < len(self.lines):
            line = self.lines[self.index]
            if line.indent != indent:
                if line.indent > indent:
                    raise YamlError(line.number, "bad indentation")
                break
            split = _split_key(line.text)
            if split is None:
                raise YamlError(line.number, f"expected 'key: value', got {line.text[:30]!r}")
            key, rest = split
            self.index += 1
            column = line.indent + len(line.text) - len(rest) + 1
            if rest:
                value = self.inline(rest, line, column - 1)
            elif self.index < len(self.lines) and self.lines[self.index].indent == indent \
                    and self.lines[self.index].text.startswith("-"):
                value = self.sequence(indent)
            else:
                value = self.child(indent, line)
            if key == "<<":
                for merged in value.value if isinstance(value.value, list) else [value]:
                    if isinstance(merged.value, dict):
                        for k, v in merged.value.items():
                            out.setdefault(k, v)
                            keys.setdefault(k, merged.key_lines.get(k, line.number))
                continue
            out[key] = value
            keys[key] = line.number
        return sized(YNode(out, first.number, first.indent + 1, keys))

    def child(self, indent: int, owner: _Line) -> YNode:
        if self.index < len(self.lines) and self.lines[self.index].indent > indent:
            return self.block(self.lines[self.index].indent)
        return YNode(None, owner.number)

    # -- inline values ---------------------------------------------------------------------------
    def inline(self, text: str, line: _Line, column: int) -> YNode:
        anchor = None
        if text.startswith("&"):
            anchor, _, text = text[1:].partition(" ")
            text = text.lstrip()
            if not text:
                node = self.child(line.indent, line)
                self.anchors[anchor] = node
                return node
        if text.startswith("*"):
            name = text[1:].strip()
            if name not in self.anchors:
                raise YamlError(line.number, f"unknown alias *{name}")
            return self.anchors[name]
        if text.startswith("!"):
            _, _, text = text.partition(" ")  # tags (!!str …) are ignored
        if text[:1] in ("|", ">"):
            node = YNode(self.block_scalar(text[0], line), line.number, column + 1)
        elif text[:1] in ("[", "{"):
            depth, quote = _flow_state(text, 0, "")
            parts = [text]
            while depth > 0 and self.index < len(self.lines):  # linear: each line scanned once
                parts.append(self.lines[self.index].text)
                depth, quote = _flow_state(parts[-1], depth, quote)
                self.index += 1
            flow = _Flow(" ".join(parts), line.number)
            value = flow.value()
            flow.end()
            node = value
            node.column = column + 1
        elif text[:1] in ("'", '"'):
            value, end = _quoted(text, 0, line.number)
            if text[end:].strip():
                raise YamlError(line.number, "text after a quoted scalar")
            node = YNode(value, line.number, column + 1)
        else:
            node = YNode(scalar(text), line.number, column + 1)
        if anchor:
            self.anchors[anchor] = node
        return node

    def block_scalar(self, style: str, owner: _Line) -> str:
        # Block scalars keep comments and blank lines: read the raw lines.
        parts: list[str] = []
        number = owner.number
        while self.index < len(self.lines) and self.lines[self.index].indent > owner.indent:
            number = self.lines[self.index].number
            self.index += 1
        body = self.raw[owner.number:number]
        if body:
            cut = min((len(r) - len(r.lstrip(" ")) for r in body if r.strip()), default=0)
            parts = [r[cut:] for r in body]
        return ("\n" if style == "|" else " ").join(parts) + "\n"


def _split_key(text: str) -> tuple[str, str] | None:
    """``key: rest`` → ``(key, rest)``; ``None`` when the line is not a mapping entry."""
    if text[:1] in ("'", '"'):
        try:
            key, end = _quoted(text, 0, 0)
        except YamlError:
            return None
        rest = text[end:]
        if rest.startswith(":") and (len(rest) == 1 or rest[1] == " "):
            return key, rest[1:].strip()
        return None
    if text[:1] in ("[", "{", "-", "&", "*", "!", "|", ">"):
        return None
    match = re.search(r":( |$)", text)
    if not match:
        return None
    return text[:match.start()].strip(), text[match.end():].strip()


def _quoted(text: str, start: int, line: int) -> tuple[str, int]:
    quote = text[start]
    out: list[str] = []
    i = start + 1
    while i < len(text):
        char = text[i]
        if quote == "'" and char == "'":
            if text[i + 1:i + 2] == "'":
                out.append("'")
                i += 2
                continue
            return "".join(out), i + 1
        if quote == '"' and char == "\\" and i + 1 < len(text):
            nxt = text[i + 1]
            out.append({"n": "\n", "t": "\t", '"': '"', "\\": "\\", "/": "/"}.get(nxt, "\\" + nxt))
            i += 2
            continue
        if quote == '"' and char == '"':
            return "".join(out), i + 1
        out.append(char)
        i += 1
    raise YamlError(line, "unterminated quoted scalar")


def _flow_state(text: str, depth: int, quote: str) -> tuple[int, str]:
    """Bracket depth and open quote after ``text``, continuing from ``depth`` and ``quote``."""
    for char in text:
        if quote:
            quote = "" if char == quote else quote
        elif char in "'\"":
            quote = char
        elif char in "[{":
            depth += 1
        elif char in "]}":
            depth -= 1
    return depth, quote


def sized(node: YNode) -> YNode:
    """``node`` with its expanded size set; :class:`YamlError` past :data:`MAX_NODES`."""
    children = node.value.values() if isinstance(node.value, dict) else \
        node.value if isinstance(node.value, list) else ()
    node.size = 1 + sum(child.size for child in children)
    if node.size > MAX_NODES:
        raise YamlError(node.line, f"more than {MAX_NODES} values once aliases are expanded")
    return node


class _Flow:
    """``[a, 'b', {c: 1}]`` on one (joined) line."""

    def __init__(self, text: str, line: int) -> None:
        self.text = text
        self.pos = 0
        self.line = line
        self.depth = 0

    def _skip(self) -> None:
        while self.pos < len(self.text) and self.text[self.pos] == " ":
            self.pos += 1

    def end(self) -> None:
        self._skip()
        if self.pos != len(self.text):
            raise YamlError(self.line, f"unexpected {self.text[self.pos:self.pos + 20]!r}")

    def value(self) -> YNode:
        if self.depth >= MAX_DEPTH:
            raise YamlError(self.line, f"collections nested deeper than {MAX_DEPTH}")
        self.depth += 1
        try:
            return self._value()
        finally:
            self.depth -= 1

    def _value(self) -> YNode:
        self._skip()
        char = self.text[self.pos:self.pos + 1]
        if char == "[":
            self.pos += 1
            items: list[YNode] = []
            while True:
                self._skip()
                if self.text[self.pos:self.pos + 1] == "]":
                    self.pos += 1
                    return sized(YNode(items, self.line))
                items.append(self.value())
                self._separator("]")
        if char == "{":
            self.pos += 1
            out: dict[str, YNode] = {}
            while True:
                self._skip()
                if self.text[self.pos:self.pos + 1] == "}":
                    self.pos += 1
                    return sized(YNode(out, self.line, key_lines={k: self.line for k in out}))
                key = self.value().value
                self._skip()
                if self.text[self.pos:self.pos + 1] != ":":
                    raise YamlError(self.line, "expected ':' in a flow mapping")
                self.pos += 1
                out[str(key)] = self.value()
                self._separator("}")
        if char in ("'", '"'):
            value, self.pos = _quoted(self.text, self.pos, self.line)
            return YNode(value, self.line)
        start = self.pos
        while self.pos < len(self.text) and self.text[self.pos] not in ",]}" and \
                not self.text.startswith(": ", self.pos):
            self.pos += 1
        if self.pos == len(self.text) and start == self.pos:
            raise YamlError(self.line, "unterminated flow collection")
        return YNode(scalar(self.text[start:self.pos].strip()), self.line)

    def _separator(self, close: str) -> None:
        self._skip()
        char = self.text[self.pos:self.pos + 1]
        if char == ",":
            self.pos += 1
        elif char != close:
            raise YamlError(self.line, f"expected ',' or '{close}' in a flow collection")


def read_yaml(source: str) -> YNode:
    """Parse one YAML document; raises :class:`YamlError` (with a line) on what it does not read."""
    try:
        return _Reader(source).document()
    except RecursionError:
        raise YamlError(1, "nested too deeply") from None
    except IndexError:
        raise YamlError(1, "unexpected end of input") from None
