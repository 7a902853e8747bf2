"""What one C++ file says about the ROS graph, as plain records (filled by :mod:`.extract`)."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from ..graph.model import Diagnostic, Location

HEADER_SUFFIXES = (".h", ".hh", ".hpp", ".hxx")


@dataclass(frozen=True)
class Owner:
    """Which node an entity is created on: a node class, one node creation, or an anonymous node."""

    kind: str  # "class" | "decl" | "anonymous"
    package: str
    name: str  # the class name, the creation's key, or the anonymous node's scope
    path: str


@dataclass(frozen=True)
class ClassFact:
    """A class definition. One in a header is the package's; one in a source file is that file's own
    (two executables of a package may each define their own ``MinimalPublisher``)."""

    package: str
    name: str
    bases: tuple[str, ...]
    location: Location

    @property
    def scope(self) -> str:
        return "" if is_header(self.location.path) else self.location.path


def is_header(path: str) -> bool:
    return path.endswith(HEADER_SUFFIXES)


@dataclass(frozen=True)
class NodeDecl:
    """A node creation: ``names``/``namespaces`` hold every possible value (``None``: unknown).

    ``cls`` is the class whose constructor passes the name to its base ``base``
    (``None`` for ``make_shared<rclcpp::Node>`` and the like, which are nodes anyway).
    """

    key: str
    names: tuple[str | None, ...]
    namespaces: tuple[str | None, ...]
    location: Location
    package: str
    cls: str | None = None
    base: str | None = None


@dataclass(frozen=True)
class EndpointFact:
    kind: str
    names: tuple[str | None, ...]
    type_written: str | None
    qos: tuple[tuple[str, Any], ...] | None
    location: Location
    owner: Owner
    written: str
    #: Where the call is: the namespaces around it and the scope its function is defined in
    #: (``fleet::Bridge`` for ``void fleet::Bridge::start()``), joined by ``::``; C++ looks a
    #: relative type (``msg::Status``) up there, innermost first.
    scope: str = ""


@dataclass(frozen=True)
class ParameterFact:
    name: str
    default: Any
    location: Location
    owner: Owner


@dataclass
class FileFacts:
    path: str
    package: str
    classes: list[ClassFact] = field(default_factory=list)
    decls: list[NodeDecl] = field(default_factory=list)
    endpoints: list[EndpointFact] = field(default_factory=list)
    parameters: list[ParameterFact] = field(default_factory=list)
    components: list[str] = field(default_factory=list)
    aliases: dict[str, str] = field(default_factory=dict)
    diagnostics: list[Diagnostic] = field(default_factory=list)
