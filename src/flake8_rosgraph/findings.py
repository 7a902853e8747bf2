"""What a check reports: the finding record and the user-tunable rule inputs.

Kept outside the ``rules`` package so that the flake8 plugin's warm path (findings
read back from the cache) imports neither the rules nor the analyser.
"""
from __future__ import annotations

from dataclasses import dataclass, field

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
