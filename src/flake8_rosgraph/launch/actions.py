"""The launch actions all three front ends produce, with substitutions left unevaluated.

A Python ``LaunchDescription``, an XML ``<launch>`` and a YAML ``launch:``
list become the same small tree of these records.  Substitutions
(``$(var x)``, ``LaunchConfiguration('x')``, ``FindPackageShare``, …) stay
symbolic here because their value depends on the scope the action runs in
(launch arguments of an include, a ``<let>`` earlier in the group); the
executor (:mod:`.execute`) evaluates them.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Union

from ..graph.model import Location


# -- substitutions ---------------------------------------------------------------------------
@dataclass(frozen=True)
class Text:
    text: str


@dataclass(frozen=True)
class Var:
    """``LaunchConfiguration('name')`` / ``$(var name)``; ``default`` if the scope has no value."""

    name: str
    default: "Subst | None" = None


@dataclass(frozen=True)
class PkgShare:
    """``FindPackageShare(pkg)``, ``$(find-pkg-share pkg)``, ``get_package_share_directory(pkg)``."""

    package: "Subst"


@dataclass(frozen=True)
class ThisDir:
    """``ThisLaunchFileDir()`` / ``$(dirname)``: the folder of the file being executed."""


@dataclass(frozen=True)
class Join:
    """Concatenation (``sep == ""``) or a path join (``sep == "/"``, absolute parts restart)."""

    parts: tuple["Subst", ...]
    sep: str = ""


@dataclass(frozen=True)
class Unknown:
    """A value the front end cannot follow; ``reason`` ends up in the report.

    ``key``: for a value computed from readable parts that the analysis does not evaluate
    (``PythonExpression([LaunchConfiguration('stream')])``), those parts: two such values
    with one key are one expression, so ``if=`` and ``unless=`` of it still exclude each
    other, though its value stays unknown."""

    reason: str
    key: "Subst | None" = None


Subst = Union[Text, Var, PkgShare, ThisDir, Join, Unknown]


# -- actions ---------------------------------------------------------------------------------
@dataclass(frozen=True)
class Condition:
    """``IfCondition``/``UnlessCondition``/``if=``/``unless=``: the action may not run."""

    expression: Subst
    negate: bool = False


@dataclass
class NodeAction:
    location: Location
    package: Subst | None
    executable: Subst | None
    name: Subst | None = None
    namespace: Subst | None = None
    remaps: list[tuple[Subst, Subst, Location]] = field(default_factory=list)
    #: ``(name, value, location)`` inline parameters; ``name`` is dotted for nested dicts.
    params: list[tuple[str, Any, Location]] = field(default_factory=list)
    param_files: list[tuple[Subst, Location]] = field(default_factory=list)
    condition: Condition | None = None
    lifecycle: bool = False
    #: Parts of the action the front end could not read (``"parameters: …"``).
    unresolved: list[str] = field(default_factory=list)


@dataclass
class GroupAction:
    location: Location
    actions: list["Action"]
    scoped: bool = True
    condition: Condition | None = None


@dataclass
class PushNamespace:
    location: Location
    namespace: Subst
    #: ``PushRosNamespace(condition=IfCondition(use_namespace), …)``: pushed only when it holds.
    condition: Condition | None = None


@dataclass
class SetRemap:
    location: Location
    source: Subst
    target: Subst
    condition: Condition | None = None


@dataclass
class SetParameter:
    location: Location
    name: str
    value: Any
    condition: Condition | None = None


@dataclass
class DeclareArgument:
    location: Location
    name: str
    default: Subst | None


@dataclass
class SetConfiguration:
    """``<let>`` / ``SetLaunchConfiguration``: overrides whatever the scope had."""

    location: Location
    name: str
    value: Subst


@dataclass
class Include:
    location: Location
    path: Subst
    #: ``None`` when the arguments passed cannot be read (they then become unknown).
    arguments: list[tuple[str, Subst]] | None = field(default_factory=list)
    condition: Condition | None = None


@dataclass
class Unsupported:
    """An action the executor does not follow (``ExecuteProcess``, ``OpaqueFunction``, …)."""

    location: Location
    what: str
    #: Whether it may start nodes the system then lacks (an ``OpaqueFunction`` may; a
    #: ``SetParameter`` of an unknown name may not).
    starts_nodes: bool = True


Action = Union[NodeAction, GroupAction, PushNamespace, SetRemap, SetParameter, DeclareArgument,
               SetConfiguration, Include, Unsupported]
