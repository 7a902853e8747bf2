"""``$(…)`` substitutions of the XML and YAML launch front ends, parsed into :mod:`.actions` terms.

The launch frontend grammar: text with ``$(name arg …)`` parts, arguments
separated by spaces, optionally single- or double-quoted, and nested
``$(…)`` allowed inside arguments.  ``var``, ``find-pkg-share`` and
``dirname`` are followed; the rest (``env``, ``eval``, ``command``,
``file-content``, …) become :class:`~.actions.Unknown` with the name in the
reason, so a report says exactly what stopped the analysis.
"""
from __future__ import annotations

from .actions import Join, PkgShare, Subst, Text, ThisDir, Unknown, Var


#: Deepest ``$(…)`` nesting followed; deeper parts are one Unknown (real files nest two or three).
MAX_SUBST_DEPTH = 16


class _Parser:
    def __init__(self, source: str) -> None:
        self.source = source
        self.pos = 0
        self.depth = 0

    def parse(self, stop: str = "") -> Subst:
        """Text and substitutions up to an unquoted character in ``stop`` (or the end)."""
        parts: list[Subst] = []
        buf: list[str] = []
        while self.pos < len(self.source):
            char = self.source[self.pos]
            if self.source.startswith("$(", self.pos):
                if buf:
                    parts.append(Text("".join(buf)))
                    buf = []
                self.pos += 2
                if self.depth >= MAX_SUBST_DEPTH:
                    parts.append(self._skip_substitution())
                    continue
                self.depth += 1
                parts.append(self._substitution())
                self.depth -= 1
                continue
            if char in stop:
                break
            buf.append(char)
            self.pos += 1
        if buf:
            parts.append(Text("".join(buf)))
        if len(parts) == 1:
            return parts[0]
        return Join(tuple(parts)) if parts else Text("")

    def _substitution(self) -> Subst:
        name = self._word()
        args: list[Subst] = []
        while self.pos < len(self.source):
            char = self.source[self.pos]
            if char == ")":
                self.pos += 1
                return _build(name, args)
            if char.isspace():
                self.pos += 1
                continue
            if char in "'\"":
                self.pos += 1
                args.append(self.parse(stop=char))
                self.pos += 1
            else:
                args.append(self.parse(stop=" \t\n)"))
        return Unknown(f"unterminated '$({name}'")

    def _skip_substitution(self) -> Subst:
        """Step over one ``$(…)`` (already opened) in linear time, without reading its parts."""
        open_parts = 1
        while self.pos < len(self.source) and open_parts:
            if self.source.startswith("$(", self.pos):
                open_parts += 1
                self.pos += 2
                continue
            if self.source[self.pos] == ")":
                open_parts -= 1
            self.pos += 1
        return Unknown(f"substitutions nested deeper than {MAX_SUBST_DEPTH} are not evaluated")

    def _word(self) -> str:
        start = self.pos
        while self.pos < len(self.source) and self.source[self.pos] not in " \t\n)":
            self.pos += 1
        return self.source[start:self.pos]


def _build(name: str, args: list[Subst]) -> Subst:
    if name == "var" and len(args) == 1 and isinstance(args[0], Unknown):
        return args[0]  # the inner reason (e.g. nesting too deep) says more than "not evaluated"
    if name == "var" and len(args) == 1 and isinstance(args[0], Text):
        return Var(args[0].text)
    if name == "find-pkg-share" and len(args) == 1:
        return PkgShare(args[0])
    if name == "dirname" and not args:
        return ThisDir()
    if name == "eval" and args:  # one expression: its if= and unless= exclude each other
        return Unknown(f"substitution $({name} …) is not evaluated statically", key=Join(tuple(args)))
    return Unknown(f"substitution $({name} …) is not evaluated statically")


def parse_substitutions(source: str) -> Subst:
    """``"$(find-pkg-share demo)/config/$(var robot).yaml"`` → a :data:`~.actions.Subst` term."""
    return _Parser(source).parse()
