"""The launch-time view of a workspace: what a launch file starts, and how.

Three front ends (Python, XML, YAML) read launch files into the same plain
records, so that instantiation (:mod:`.instantiate`) and the ROS2xx rules do
not care which syntax a file used.  A value a front end cannot pin down is
``None`` plus an entry in :attr:`LaunchedNode.unresolved` saying why — never a
guess, because a guessed namespace would invent connections.
"""
from __future__ import annotations

import posixpath
from dataclasses import dataclass, field
from typing import Any

from ..graph.model import Diagnostic, Location, RosNode
from .actions import Join, Subst, Text, Unknown
from .param_files import Section

#: A condition an action runs under: its expression, and whether it is negated.
Guard = tuple[Subst, bool]


@dataclass(frozen=True, order=True)
class Remap:
    """One ``from:=to`` rule as the launch file wrote it (substitutions resolved)."""

    source: str
    target: str
    location: Location
    #: Set by a ``SetRemap`` of the scope (for every node there), not by this node.
    from_scope: bool = False


@dataclass(frozen=True, order=True)
class ParamValue:
    """A parameter set inline (``parameters=[{...}]``, ``<param name= value=>``, ``SetParameter``)."""

    name: str
    value: Any
    location: Location
    #: Set by a ``SetParameter`` of the scope (meant for every node there), not for this node.
    from_scope: bool = False


@dataclass(frozen=True, order=True)
class ParamFileRef:
    """A parameter YAML file handed to a node; ``path`` is root-relative, ``None`` when unresolved."""

    path: str | None
    location: Location
    written: str = ""  # the reference as the launch file wrote it, for messages


@dataclass(frozen=True)
class ExecutableRef:
    """Where ``package`` + ``executable`` lead in the workspace.

    ``status`` is ``"found"`` (code nodes known), ``"no-python"`` (a real
    executable the analyser cannot look into: C++, a script it cannot map),
    ``"missing-package"`` (the package is not in the workspace: an installed
    one, not judged), ``"missing-executable"`` (the package is in the
    workspace and has no such executable: ROS201) or ``"unknown"`` (the
    package or executable name is not known statically).
    """

    status: str
    #: Locations of the code-level nodes the executable creates (keys into the code graph).
    node_sites: tuple[Location, ...] = ()
    #: Node sites whose code allows undeclared parameters (any override is accepted).
    open_parameter_sites: tuple[Location, ...] = ()
    #: ``(site, class)`` of every node object the executable creates: a base class's
    #: ``super().__init__`` site is shared by its subclasses, and only the classes the
    #: executable instantiates are its nodes.
    node_classes: tuple[tuple[Location, str | None], ...] = ()
    #: ``module:function`` the executable runs, for the JSON output.
    entry: str | None = None
    #: Where ends are created on its nodes by code only other executables of the same node
    #: class reach (their ``main``): not its ends (:mod:`.targets`).
    foreign_end_sites: tuple[Location, ...] = ()
    #: The executables the package does have, for the ROS201 message.
    known: tuple[str, ...] = ()
    #: A C++ executable (``"no-python"``): its source files and component classes as CMake names
    #: them, which tie it to the workspace's rclcpp nodes (:mod:`.instantiate`).
    cpp_sources: tuple[str, ...] = ()
    cpp_plugins: tuple[str, ...] = ()
    #: The sources of the package libraries it links: where its node class lives when its own
    #: sources only ``main`` (used when they hold one node class, so the tie is not a guess).
    cpp_linked: tuple[str, ...] = ()


@dataclass
class LaunchedNode:
    """One ``Node``/``LifecycleNode`` action, with everything its scope adds.

    ``name`` and ``namespace`` are the launch overrides (``__node``/``__ns``);
    ``None`` means "not overridden" unless the field is listed in
    ``unresolved``, in which case the launch file sets it to something
    the analysis cannot determine.  ``remaps`` are in rcl's order: the
    scope's ``SetRemap`` rules first, then the node's own.  ``params`` and
    ``param_files`` are in the order launch passes them (global first).
    """

    package: str | None
    executable: str | None
    location: Location
    launch_file: str
    name: str | None = None
    namespace: str | None = None
    remaps: list[Remap] = field(default_factory=list)
    params: list[ParamValue] = field(default_factory=list)
    param_files: list[ParamFileRef] = field(default_factory=list)
    conditional: bool = False
    #: The readable conditions it runs under: ``(expression, negated)``. Nodes of one launch
    #: file under ``if=X`` and ``unless=X`` never run together.
    guards: tuple[Guard, ...] = ()
    lifecycle: bool = False
    unresolved: list[str] = field(default_factory=list)
    target: ExecutableRef = ExecutableRef("unknown")

    def excludes(self, other: "LaunchedNode") -> bool:
        """Whether this node and ``other`` (of the same launch) never both start: one runs
        under a condition the other runs under negated, or under the same comparison with
        ``==`` and ``!=`` swapped (``$(eval '"$(var m)" != ""')`` and ``… == ""``)."""
        return any((expression, not negated) in other.guards
                   or any(negated == theirs and _opposite_comparisons(expression, mine_other)
                          for mine_other, theirs in other.guards)
                   for expression, negated in self.guards)

    def is_unresolved(self, what: str) -> bool:
        return any(u.split(":", 1)[0] == what for u in self.unresolved)


@dataclass
class Instance:
    """A launched node bound to a code-level node: the node as rcl would create it.

    ``settings`` are the parameters that reach the node (``(name, value,
    location, origin)``, origin ``"scope"``, ``"inline"``, ``"file"`` or ``"shared file"``, a
    file section with a wildcard such as ``/**``);
    ``remap_hits`` the indexes of ``launched.remaps`` that matched a name.
    """

    launched: LaunchedNode
    node: RosNode
    code: RosNode
    remap_hits: frozenset[int] = frozenset()
    settings: list[tuple[str, Any, Location, str]] = field(default_factory=list)
    #: Every named entity of the node has a known name, so "matches nothing" is a fact.
    names_known: bool = True
    #: The node's names expanded in its launched name and namespace, before remapping.
    expanded: tuple[str, ...] = ()
    #: Whether the node's code is analysed in full (Python); a C++ node is bound for its names
    #: only, and the rules that judge what a node lacks (ROS202, ROS204) leave it out.
    analysed: bool = True


@dataclass
class System:
    """Everything one launch file (and what it includes) starts.

    ``files`` lists the launch files read, the root file first; ``problems``
    are the parts that could not be followed (an include that does not
    resolve, an ``OpaqueFunction``): reported, not guessed.
    """

    launch_file: str
    nodes: list[LaunchedNode] = field(default_factory=list)
    files: list[str] = field(default_factory=list)
    arguments: dict[str, str | None] = field(default_factory=dict)
    problems: list[Diagnostic] = field(default_factory=list)
    instances: list[Instance] = field(default_factory=list)
    #: The sections of every parameter file its nodes are given (root-relative path → sections).
    parameter_files: dict[str, list[Section]] = field(default_factory=dict)
    #: Where it runs actions that may start nodes the analysis cannot see (an ``OpaqueFunction``
    #: it cannot follow): those nodes, with their names and remaps, are not in ``nodes``.
    unfollowed: list[Location] = field(default_factory=list)
    #: The argument values handed to each include it does not follow (an installed package's
    #: launch file): ``None`` for a value it cannot read, or for the whole list when the
    #: arguments cannot be read. A parameter file reaches that launch file's nodes only so.
    unseen_includes: list[tuple[str | None, ...] | None] = field(default_factory=list)
    #: Some launch file of it was not read or followed at all (unreadable, recursive, over the
    #: include budget): what it starts, with which files, is not known.
    blind: bool = False

    def may_hand_unseen(self, path: str) -> bool:
        """Whether this system may hand the parameter file ``path`` to nodes the analysis does not
        see: an action it does not follow that may start nodes, or an include it does not follow
        handed an argument that names the file or cannot be read."""
        name = posixpath.basename(path)
        return self.blind or bool(self.unfollowed) or any(
            handed is None or any(value is None or name in value for value in handed)
            for handed in self.unseen_includes)

    @property
    def complete(self) -> bool:
        """Whether every node was instantiated with every value known."""
        return not self.problems and all(not n.unresolved for n in self.nodes)


def _opposite_comparisons(a: Subst, b: Subst) -> bool:
    """Two unevaluated expressions alike but for one ``==`` that is ``!=`` in the other."""
    parts_a, parts_b = _expression_parts(a), _expression_parts(b)
    if parts_a is None or parts_b is None or len(parts_a) != len(parts_b):
        return False
    differing = [(x, y) for x, y in zip(parts_a, parts_b) if x != y]
    return len(differing) == 1 and all(isinstance(p, Text) for p in differing[0]) and (
        differing[0][0].text.replace("!=", "==") == differing[0][1].text
        or differing[0][1].text.replace("!=", "==") == differing[0][0].text) and (
        differing[0][0].text.count("!=") + differing[0][1].text.count("!=") == 1)


def _expression_parts(expression: Subst) -> tuple | None:
    """The parts of an unevaluated expression (``Unknown`` with a key), flattened."""
    if not isinstance(expression, Unknown) or expression.key is None:
        return None
    return tuple(_flat(expression.key))


def _flat(term: Subst) -> list[Subst]:
    if isinstance(term, Join) and not term.sep:
        return [part for inner in term.parts for part in _flat(inner)]
    return [term]
