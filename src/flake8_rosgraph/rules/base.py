"""What every rule shares: the finding record, the rule configuration, the rule base class.

A rule reads a :class:`~flake8_rosgraph.graph.model.RosGraph` (never source code)
and yields :class:`Finding` objects located at the site a developer can fix.
"""
from __future__ import annotations

from typing import ClassVar, Iterator

from ..findings import Finding, RuleConfig
from ..graph.model import RosGraph

__all__ = ["Finding", "Rule", "RuleConfig"]


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
