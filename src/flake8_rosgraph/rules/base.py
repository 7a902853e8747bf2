"""What every rule shares: the finding record, the rule configuration, the rule base class.

A rule reads a :class:`~flake8_rosgraph.graph.model.RosGraph` (never source code)
and yields :class:`Finding` objects located at the site a developer can fix.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import ClassVar, Iterator

from ..graph.model import Location, RosGraph


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


class Rule:
    """Base class: subclasses set the class attributes and implement :meth:`check`.

    The subclass docstring is the rule's documentation (ruff style: What it does /
    Why is this bad? / Known problems / Example / Use instead / Options).
    """

    code: ClassVar[str]
    name: ClassVar[str]
    level: ClassVar[str]  # "error" | "warning" | "note"
    summary: ClassVar[str]
    precision: ClassVar[str]  # SARIF precision: "very-high" | "high" | "medium" | "low"
    default_enabled: ClassVar[bool] = True

    def check(self, graph: RosGraph, config: RuleConfig) -> Iterator[Finding]:
        raise NotImplementedError
