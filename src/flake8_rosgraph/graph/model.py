"""The extracted ROS computation graph: plain data, no analysis.

Everything downstream (rules, JSON/DOT/SARIF writers, the flake8 adapter) reads
these classes and nothing else, so they stay small, immutable where it is cheap,
and free of any knowledge of how they were found.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

#: The entity kinds in the order of the graph JSON contract.
KINDS: tuple[str, ...] = (
    "publishers", "subscriptions", "services", "clients",
    "action_servers", "action_clients", "timers", "parameters",
)
#: Kinds whose entities carry a resolved ROS name (topic, service or action).
NAMED_KINDS: tuple[str, ...] = KINDS[:6]
#: For each named kind, the kind at the other end of the connection.
PEER_KIND: dict[str, str] = {
    "publishers": "subscriptions", "subscriptions": "publishers",
    "services": "clients", "clients": "services",
    "action_servers": "action_clients", "action_clients": "action_servers",
}


@dataclass(frozen=True, order=True)
class Location:
    """A place in the analysed workspace: root-relative POSIX path, 1-based line and character column."""

    path: str
    line: int
    column: int

    def short(self) -> str:
        return f"{self.path}:{self.line}"


@dataclass(frozen=True)
class Entity:
    """A publisher, subscription, service, client, action server/client, timer or parameter.

    ``name`` is the fully resolved ROS name (``None`` when the analysis cannot tell);
    ``raw_name`` is the name as written in code before expansion. For timers
    ``name`` is ``None`` and ``period`` holds the period; for parameters ``name``
    is the parameter name and ``default`` its default value.
    """

    kind: str
    name: str | None
    location: Location
    raw_name: str | None = None
    type: str | None = None
    qos: dict[str, Any] | None = None
    callback: str | None = None
    period: float | None = None
    default: Any = None
    conditional: bool = False
    invalid: str | None = None  # why the name breaks the rcl rules, if it does
    via: str | None = None      # library class that implies this entity (tf2_ros, parameter client)
    #: The name as written at the creating call (``prefix + '/scan'``), to say what could not be resolved.
    name_text: str | None = None
    #: For an unknown ``name``: how it ends when only what rcl puts in front is unknown (the
    #: namespace of a relative name, the node of a private one) and no remap can change it —
    #: ``'/amcl_pose'`` for ``'amcl_pose'`` on a node of unknown namespace. An unknown with a
    #: known end can only be the other end of names that end so.
    name_suffix: str | None = None
    #: The name is one known alternative of a name that may also be something unknown
    #: (``param if launched else '/scan'``); the unknown rest is an entity of its own with
    #: name ``None`` at the same location.
    partial: bool = False
    #: The name is built from parameters of its node (``declare_parameter('topic', 'scan')`` …
    #: ``create_subscription(T, self.get_parameter('topic').value, …)``, or ``ns + '/scan'``):
    #: its parts in order, each ``(parameter, default)`` — a parameter's name and the one
    #: string it defaults to (``None``: no known default), or ``("", text)`` for plain text.
    #: ``name`` is what the defaults give (``None`` without them); a launch file or parameter
    #: file that sets the parameters names the entity where it starts the node.
    name_template: tuple[tuple[str, str | None], ...] | None = None
    #: Where the launch file or parameter file that names the entity sets its (first)
    #: parameter (for a launched node only), so that a finding can point at the value.
    name_set_at: Location | None = None
    #: The creation site runs in several calls of a shared helper (``self._client(T, '/a')``,
    #: ``self._client(T, '/b')`` through one ``create_client``), and one of them names this end
    #: alone: the site's other names are other ends, not other configurations of this one.
    own_call: bool = False

    @property
    def from_parameter(self) -> str | None:
        """The one parameter the whole name is, or ``None``."""
        if self.name_template is not None and len(self.name_template) == 1:
            return self.name_template[0][0] or None
        return None

    @property
    def name_parameters(self) -> tuple[str, ...]:
        """The parameters the name is built from, in order."""
        return tuple(parameter for parameter, _ in self.name_template or () if parameter)


@dataclass
class RosNode:
    """A ROS node the code can create, with the entities created on it."""

    name: str | None
    namespace: str | None
    location: Location
    cls: str | None = None
    conditional: bool = False
    #: The file that defines the node's class (``cls``), when it is a workspace class: the
    #: creation site (``location``) is a base class's ``super().__init__`` for a subclass.
    cls_path: str | None = None
    invalid: str | None = None
    entities: list[Entity] = field(default_factory=list)
    #: Where a launch file starts this node ({"file", "line", "package", "executable", …});
    #: ``None`` for the node as written in code.
    launch: dict[str, Any] | None = None
    #: The language of the code that creates it: ``"python"`` (rclpy, analysed) or ``"cpp"``
    #: (rclcpp, read by :mod:`flake8_rosgraph.cpp` as a partner end for the Python rules).
    language: str = "python"
    #: What the node's own ``cli_args`` set (``"name"``, ``"namespace"``): rcl reads a node's
    #: local arguments before the process's, so a launch file's ``name``/``namespace`` do
    #: not replace them.
    local_overrides: tuple[str, ...] = ()
    #: For a node presumed from Node API calls in a class whose base class is not resolved
    #: (an import no stub models): that base class. Its name and namespace are unknown.
    unresolved_base: str | None = None
    #: For a node a function receives through a parameter annotated with a node class from
    #: no analysed caller (:mod:`~flake8_rosgraph.absint.passed_in`): ``"<parameter> of
    #: <function>"``. Its name and namespace are whatever the caller's node has: unknown.
    passed_in: str | None = None
    #: Names the node's class writes as arguments of calls that hand the node to code the
    #: analysis cannot see (:mod:`.unseen_calls`): it may use them, in some role, through
    #: that code — as written, not expanded.
    unseen_names: tuple[str, ...] = ()

    @property
    def fqn(self) -> str | None:
        if self.name is None or self.namespace is None:
            return None
        return self.namespace.rstrip("/") + "/" + self.name

    def of_kind(self, kind: str) -> list[Entity]:
        return [e for e in self.entities if e.kind == kind]


@dataclass(frozen=True, order=True)
class Diagnostic:
    """A gap in the analysis (unparsable file, budget hit, broken stub) — never a finding."""

    path: str
    line: int
    message: str
    severity: str = "warning"


def internal_error(what: str, exc: Exception) -> Diagnostic:
    """The error diagnostic of a defect of this tool that cost ``what`` (``"packages not read"``)."""
    return Diagnostic("", 0, f"{what}: internal error: {type(exc).__name__}: {exc}", "error")


@dataclass
class RosGraph:
    """The whole-workspace graph: nodes plus the diagnostics gathered while building it."""

    nodes: list[RosNode] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)
    #: The launch systems found in the workspace (``flake8_rosgraph.launch.System``).
    systems: list[Any] = field(default_factory=list)
    #: What the code builds, fills in and publishes (``flake8_rosgraph.graph.messages.MessageFacts``).
    messages: Any = None
    #: The interface definitions known (``flake8_rosgraph.interfaces.catalogue.Catalogue``).
    interfaces: Any = None
    #: How the code uses rclpy beyond the graph (``flake8_rosgraph.graph.usage.UsageFacts``:
    #: callbacks, blocking calls, executors, parameter uses); ``None`` when not extracted.
    usage: Any = None
    #: The SROS2 access-control profiles of the workspace's policy files
    #: (``flake8_rosgraph.security.policy.PolicyProfile``).
    policies: list[Any] = field(default_factory=list)

    def entities(self, kind: str | None = None):
        """Yield ``(node, entity)`` pairs, optionally of one kind."""
        for node in self.nodes:
            for ent in node.entities:
                if kind is None or ent.kind == kind:
                    yield node, ent
