"""ROS parameter YAML files: which settings reach which node, with lines.

The layout rcl's parameter parser reads (``rcl_yaml_param_parser``): keys
down to ``ros__parameters`` name the node (``talker``, ``/ns/talker``,
nested ``ns: talker:``, or with ``*`` for one name token and ``/**`` for any
number of them); below it, nested mappings are flattened into dotted
parameter names.  A key without a leading ``/`` is absolute all the same.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ..graph.model import Location
from ..safe_io import read_text
from .yaml_reader import YamlError, YNode, read_yaml

PARAMS_KEY = "ros__parameters"


@dataclass(frozen=True)
class Section:
    """One ``<node pattern>: ros__parameters:`` block; ``location`` is its innermost node key."""

    pattern: str
    settings: tuple[tuple[str, Any, Location], ...]
    #: The line of the key that holds ``ros__parameters`` (the node key), for ROS205.
    location: Location | None = None

    @property
    def shared(self) -> bool:
        """A section with a wildcard (``/**``, ``*``) is meant for every node it matches."""
        return "*" in self.pattern

    def matches(self, fqn: str) -> bool:
        return _pattern_regex(self.pattern).fullmatch(fqn) is not None


def _pattern_regex(pattern: str) -> re.Pattern:
    out = []
    i = 0
    while i < len(pattern):
        if pattern.startswith("/**", i):
            out.append("(/[^/]+)*")
            i += 3
        elif pattern[i] == "*":
            out.append("[^/]+")
            i += 1
        else:
            out.append(re.escape(pattern[i]))
            i += 1
    return re.compile("".join(out))


def _flatten(node: YNode, prefix: str, path: str, out: list[tuple[str, Any, Location]]) -> None:
    if not isinstance(node.value, dict):
        return
    for key, value in node.value.items():
        name = prefix + key
        if isinstance(value.value, dict) and value.value:
            _flatten(value, name + ".", path, out)
        else:
            out.append((name, value.plain(), Location(path, node.key_lines.get(key, value.line), 1)))


def _sections(node: YNode, tokens: list[str], path: str, out: list[Section], line: int = 1) -> None:
    if not isinstance(node.value, dict):
        return
    for key, value in node.value.items():
        key_line = node.key_lines.get(key, value.line)
        if key == PARAMS_KEY:
            pattern = "/".join(t.strip("/") for t in tokens if t.strip("/"))
            settings: list[tuple[str, Any, Location]] = []
            _flatten(value, "", path, settings)
            out.append(Section("/" + pattern, tuple(settings), Location(path, line, 1)))
        else:
            _sections(value, tokens + [key], path, out, key_line)


def read_param_file(root: Path, path: str) -> list[Section]:
    """The sections of the parameter file at ``path`` (root-relative); raises ``YamlError``/``OSError``."""
    text = read_text(Path(root) / path, Path(root))
    out: list[Section] = []
    _sections(read_yaml(text), [], path, out)
    return out


__all__ = ["Section", "read_param_file", "YamlError"]
