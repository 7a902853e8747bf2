"""What a check reports: the finding record and the user-tunable rule inputs.

Kept outside the ``rules`` package so that the flake8 plugin's warm path (findings
read back from the cache) imports neither the rules nor the analyser.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

from .graph.model import Location


@dataclass(frozen=True, order=True)
class Finding:
    """One reported problem: code, one-line message, where, and the other end(s)."""

    location: Location
    code: str
    message: str
    related: tuple[tuple[Location, str], ...] = ()


@dataclass(frozen=True)
class RuleConfig:
    """User-tunable inputs of the rules (flake8 options, env vars, CLI flags)."""

    #: Topics/services/actions handled outside the workspace, on top of the built-in exempt list.
    external_names: frozenset[str] = field(default_factory=frozenset)


def display_path(path: Path) -> str:
    """A path as the user would type it: relative to the current folder when inside it."""
    try:
        return path.relative_to(Path.cwd()).as_posix()
    except ValueError:
        return path.as_posix()


def localised_message(root: Path, finding: Finding) -> str:
    """The message with the other ends' workspace-relative ``path:line`` made relative to the current folder."""
    shown = {f"{location.path}:{location.line}": f"{display_path(root / location.path)}:{location.line}"
             for location, _ in finding.related}
    if not shown:
        return finding.message
    # One pass over the text: two ends at one line are rewritten once, and ``x.py:13`` is not
    # rewritten inside ``x.py:136`` or inside a path that was already rewritten.
    pattern = "|".join(re.escape(key) for key in sorted(shown, key=len, reverse=True))
    return re.sub(rf"(?<![\w./-])(?:{pattern})(?!\d)", lambda m: shown[m.group(0)], finding.message)
