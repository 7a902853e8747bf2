"""ROS007 duplicate-node-name."""
from __future__ import annotations

from collections import defaultdict
from typing import Iterator

from ..graph.model import PEER_KIND, Location, RosGraph, RosNode
from ..launch.model import LaunchedNode
from .base import Finding, Rule, RuleConfig
from .fixtures import node_scope, test_run
from .topics import Endpoint, EndpointIndex
from .vocabulary import NAME_NOUN
from .written import launched_names, written_graph


#: Topics every node joins whatever system it belongs to: the log, parameter events and the
#: transform tree (a TransformListener hears every broadcaster). Using them ties no two nodes
#: together; ``/clock`` does (a simulator and the nodes on its time), as does any other name.
SHARED_BUSES = frozenset({"/rosout", "/parameter_events", "/tf", "/tf_static"})


class DuplicateNodeName(Rule):
    """## What it does
    Checks for two node creation sites that resolve to the same fully
    qualified node name and run together: both started by one launch file
    (with what it includes), both created in one source file (one process),
    or talking to each other (one publishes a topic the other subscribes,
    serves a service or action the other calls: a system split over several
    launch files still runs as one; `/rosout`, `/parameter_events` and the
    transform tree `/tf`, `/tf_static`, which every node joins whatever system it
    belongs to, tie no two nodes together, while `/clock` does). The finding is reported at
    both sites, each with the other as related location: the creation site
    in code, or the launch action when a launch file sets the node's name
    (so one executable launched twice under one name is reported too).
    Nodes a launch file starts whose code is not in the workspace (components
    loaded into a container, installed executables) are compared by the name
    and namespace the launch file gives them. Programs also run as written
    (`ros2 run`): two nodes whose code gives them one name, that talk to each
    other as written, are reported at their creation sites though the launch
    files start them under other names (a node name copied from the program
    it talks to, hidden by `Node(..., name='tts')`).

    ## Why is this bad?
    ROS 2 does not enforce unique node names: both nodes start, but tools
    (`ros2 node`, `ros2 param`, lifecycle management, launch's event handlers)
    address nodes by name and then reach only one of them, or either at
    random, and the parameter services of the two collide.

    ## Known problems
    Nodes of one name in files that are neither launched together nor
    connected are alternative programs (tutorial variants such as
    `minimal_publisher` in three styles), so they are not compared. Test
    files are not one process: a pytest module that creates a node of the
    same name in each test function is quiet, unless its nodes talk to each
    other or one launch test starts them; the nodes of two test modules in a
    test folder never talk to each other, and a test module's node never runs beside a node
    a production launch file starts (a test that hosts the node under test under its product
    name stands in for the launched product, however the two would talk). Two classes in two modules that one
    `main` instantiates together are not seen as one process (the graph does
    not record which entry point creates a node). Alternatives of one
    creation site (`Node('a' if x else 'b')`) and nodes created by one call
    inside a loop are one site and are not reported. One node's code started
    under one name by two launch files that do not start each other's
    instance (two bring-ups of one safety monitor, one remapping its output
    onto what the other's input reads) is two deployments: their talk does
    not make them run together; so are the nodes of one executable that two
    such launch files start. An end whose name rclpy rejects (ROS006)
    never exists, so it ties no two nodes together; nor does a topic that
    both nodes publish and subscribe (a state channel two alternative programs
    of one role each announce on and listen to: each hears itself there too).

    ## Example
    ```python
    # camera_driver/driver.py
    super().__init__('camera')
    self.create_publisher(Image, 'image_raw', 10)
    # camera_driver/viewer.py
    super().__init__('camera')
    self.create_subscription(Image, 'image_raw', self.show, 10)
    ```

    ## Use instead
    ```python
    # camera_driver/viewer.py
    super().__init__('camera_viewer')
    ```

    ## Options
    None.
    """

    code = "ROS007"
    name = "duplicate-node-name"
    level = "warning"
    precision = "medium"  # SARIF/code-scanning precision: how often a finding is a real problem
    summary = "two nodes that can run together resolve to the same fully qualified name"

    def check(self, graph: RosGraph, config: RuleConfig) -> Iterator[Finding]:
        groups = _by_name(graph)
        together = _Together(graph, [fqn for fqn, nodes in groups.items() if len(nodes) > 1])
        judged = [finding for fqn in sorted(groups) for finding in self._duplicates(fqn, groups[fqn], together)]
        yield from judged
        reported: dict[Location, Finding] = {}
        for finding in self._launched_without_code(graph):  # an included file: its includers' too
            reported.setdefault(finding.location, finding)
        yield from (reported[location] for location in sorted(reported))
        yield from self._as_written(graph, {finding.location for finding in judged})

    def _as_written(self, graph: RosGraph, reported: set[Location]) -> Iterator[Finding]:
        """Nodes whose code gives them one name, that run together as written (``ros2 run``: they
        talk, or one file creates both) but that the launch files start under other names: the
        launched system hides the clash, running the programs as written does not."""
        written = written_graph(graph)
        if written is None:
            return
        groups = _by_name(written)
        runs_as = launched_names(graph)
        duplicated = [fqn for fqn, nodes in groups.items()
                      if len(nodes) > 1 and any(id(node) in runs_as for node in nodes)]
        together = _LaunchedApart(written, duplicated, runs_as)
        for fqn in sorted(duplicated):
            for finding in self._duplicates(fqn, groups[fqn], together):
                if finding.location not in reported:
                    yield Finding(finding.location, self.code, finding.message + _AS_WRITTEN, finding.related)

    def _launched_without_code(self, graph: RosGraph) -> Iterator[Finding]:
        """Two nodes one launch file starts unconditionally under one name it gives in full,
        neither tied to code of the workspace (components, installed executables): the code
        pass above cannot see them, but the names alone clash."""
        for system in graph.systems:
            first: dict[str, tuple[Location, bool]] = {}
            # C++ executables tied to their code are also in the code pass: a pair of those is its.
            bound = {id(instance.launched) for instance in system.instances}
            for launched in system.nodes:
                if launched.target.status == "found" or launched.conditional or launched.name is None \
                        or launched.namespace is None or launched.unresolved:
                    continue
                fqn = launched.namespace.rstrip("/") + "/" + launched.name
                if fqn in first:
                    where, first_bound = first[fqn]
                    if first_bound and id(launched) in bound:
                        continue
                    yield Finding(launched.location, self.code,
                                  f"node '{fqn}' is also started at {where.short()} by the same "
                                  f"launch file {system.launch_file}", ((where, f"node '{fqn}'"),))
                else:
                    first[fqn] = (launched.location, id(launched) in bound)

    def _duplicates(self, fqn: str, nodes: list[RosNode], together: _Together) -> Iterator[Finding]:
        # site -> partner site -> why they run together (the first reason found, in a fixed order)
        partners: dict[Location, dict[Location, str]] = defaultdict(dict)
        # A launch action naming an executable that creates several nodes renames them all alike.
        renamed_together: dict[Location, set[Location]] = defaultdict(set)
        for reason, a, b in together.pairs(nodes):
            site_a, site_b = together.site(a), together.site(b)
            if site_a != site_b:
                partners[site_a].setdefault(site_b, reason)
                partners[site_b].setdefault(site_a, reason)
            elif a.location != b.location and site_a != a.location and a.language == b.language == "python":
                # (the C++ front end's nodes are groups of partner ends, not each a creation)
                renamed_together[site_a] |= {a.location, b.location}
        for site in sorted(renamed_together):
            created = sorted(renamed_together[site])
            message = (f"node '{fqn}': this launch action gives its name to every node the executable "
                       f"creates ({', '.join(c.short() for c in created)}), so they run under one name")
            yield Finding(site, self.code, message, tuple((c, "node created here") for c in created))
        for site in sorted(partners):
            others = sorted(partners[site])
            first = others[0]
            message = (f"node '{fqn}' is also created at {first.short()}, "
                       f"and they run together ({partners[site][first]})")
            yield Finding(site, self.code, message, tuple((o, f"node '{fqn}'") for o in others))


class _Together:
    """Which nodes of one name run together, from the launch systems, the files and the wiring."""

    def __init__(self, graph: RosGraph, duplicated: list[str]) -> None:
        wanted = set(duplicated)
        self._systems: dict[int, list[str]] = defaultdict(list)
        self._named_at: dict[int, Location] = {}
        #: The launch action that starts a node, per launch file (the first, if several).
        self._started_by: dict[tuple[int, str], LaunchedNode] = {}
        for system in graph.systems:
            for instance in system.instances:
                if instance.node.fqn in wanted:
                    self._systems[id(instance.node)].append(system.launch_file)
                    launched = instance.launched
                    self._started_by.setdefault((id(instance.node), system.launch_file), launched)
                    if launched.name is not None:
                        self._named_at[id(instance.node)] = Location(
                            launched.launch_file, launched.location.line, launched.location.column)
        self._index = EndpointIndex.build(graph) if wanted else None

    def site(self, node: RosNode) -> Location:
        """Where to fix the name: the launch action that names the node, else the node's creation site."""
        return self._named_at.get(id(node), node.location)

    def pairs(self, nodes: list[RosNode]) -> Iterator[tuple[str, RosNode, RosNode]]:
        """``(why, a, b)`` for nodes of ``nodes`` that run together, launch first, then file, then wiring.

        Each relation is bucketed (by launch file, by file, by name used), so
        the work is linear in the nodes and their entities, not in their pairs.
        """
        ordered = sorted(nodes, key=lambda n: (n.location, repr(n.launch)))
        by_launch: dict[str, list[RosNode]] = defaultdict(list)
        by_file: dict[str, list[RosNode]] = defaultdict(list)
        for node in ordered:
            for launch_file in sorted(set(self._systems.get(id(node), ()))):
                by_launch[launch_file].append(node)
            # A file is one process for code run as written; a launched node's process is its launch
            # action, and test functions are separate processes.
            if node.launch is None and node_scope(node) is None:
                by_file[node.location.path].append(node)
        for launch_file, started in sorted(by_launch.items()):
            yield from self._started_together(launch_file, started)
        for _, created in sorted(by_file.items()):
            yield from _chained("both are created in this file", created)
        yield from self._talking(ordered)

    def _started_together(self, launch_file: str, started: list[RosNode]
                          ) -> Iterator[tuple[str, RosNode, RosNode]]:
        """Nodes of one launch file paired with the first earlier node that can run beside them:
        under ``if=X`` and ``unless=X`` they never both start."""
        actions = [self._started_by[(id(node), launch_file)] for node in started]
        for index in range(1, len(started)):
            partner = next((earlier for earlier in range(index)
                            if not actions[earlier].excludes(actions[index])), None)
            if partner is not None:
                yield f"both are started by {launch_file}", started[partner], started[index]

    def _talking(self, nodes: list[RosNode]) -> Iterator[tuple[str, RosNode, RosNode]]:
        if self._index is None:
            return
        members = {id(n) for n in nodes}
        for node in nodes:
            scope = node_scope(node)
            for entity in node.entities:
                if entity.name is None or entity.kind not in PEER_KIND or entity.name in SHARED_BUSES \
                        or entity.invalid is not None:  # rclpy raises before such an end exists
                    continue
                for peer in self._index.peers(Endpoint(node, entity, scope)):
                    if id(peer.node) in members and peer.node is not node \
                            and not self._configurations_of_one_node(node, peer.node) \
                            and not _unit_test_beside_launched(node, peer.node) \
                            and not (_on_bus(node, entity.name) and _on_bus(peer.node, entity.name)):
                        yield f"they talk over {NAME_NOUN[entity.kind]} '{entity.name}'", node, peer.node

    def _configurations_of_one_node(self, a: RosNode, b: RosNode) -> bool:
        """Whether ``a`` and ``b`` are one node's code as launch files that do not start each
        other's instance configure it (a safety monitor whose output one bring-up remaps onto
        what another bring-up's instance reads): each is a deployment of its own, and one
        launch file starting both is reported above."""
        return (a.location == b.location or _one_executable(a, b)) \
            and a.launch is not None and b.launch is not None \
            and not set(self._systems.get(id(a), ())) & set(self._systems.get(id(b), ()))


def _one_executable(a: RosNode, b: RosNode) -> bool:
    """Whether two launched nodes come from one executable (the nodes one process creates,
    each given the launch action's name)."""
    return a.launch is not None and b.launch is not None and a.launch.get("package") is not None \
        and (a.launch.get("package"), a.launch.get("executable")) == \
        (b.launch.get("package"), b.launch.get("executable"))


def _unit_test_beside_launched(a: RosNode, b: RosNode) -> bool:
    """A node a unit test creates (no launch file starts it) and a node a production launch
    file starts: the test process runs on its own, the launch file is not part of it."""
    def launched(node: RosNode) -> bool:
        return node.launch is not None and node_scope(node) is None
    return test_run(a) is not None and launched(b) or test_run(b) is not None and launched(a)


def _on_bus(node: RosNode, name: str) -> bool:
    """Whether ``node`` both publishes and subscribes topic ``name``. Two alternative programs
    of one role (an audio input run locally or in the cloud) that each announce their state on
    a shared channel and listen to it hear each other there as they hear themselves: that is
    no sign that they run together."""
    roles = {e.kind for e in node.entities if e.name == name}
    return {"publishers", "subscriptions"} <= roles


#: What a finding of :meth:`DuplicateNodeName._as_written` adds to say where the names clash.
_AS_WRITTEN = " when started as written in code (`ros2 run`), without the launch files that rename them"


class _LaunchedApart(_Together):
    """Nodes of one written name that run together as written, and that no launch file starts
    under one name (the judged graph compares those): launch renames them apart."""

    def __init__(self, written: RosGraph, duplicated: list[str],
                 runs_as: dict[int, frozenset[str | None]]) -> None:
        super().__init__(written, duplicated)
        self._runs_as = runs_as

    def pairs(self, nodes: list[RosNode]) -> Iterator[tuple[str, RosNode, RosNode]]:
        for reason, a, b in super().pairs(nodes):
            if not (self._names(a) & self._names(b)) - {None}:
                yield reason, a, b

    def _names(self, node: RosNode) -> frozenset[str | None]:
        return self._runs_as.get(id(node), frozenset({node.fqn}))


def _by_name(graph: RosGraph) -> dict[str, list[RosNode]]:
    """The nodes of ``graph`` whose fully qualified name is known, by that name."""
    groups: dict[str, list[RosNode]] = defaultdict(list)
    for node in graph.nodes:
        if node.fqn is not None:
            groups[node.fqn].append(node)
    return groups


def _chained(reason: str, nodes: list[RosNode]) -> Iterator[tuple[str, RosNode, RosNode]]:
    """The nodes of one bucket (which all run together) paired so that every site has a partner.

    The first node is paired with each node of another site: linear, where
    all pairs would be quadratic in the size of the bucket.
    """
    for node in nodes[1:]:
        yield reason, nodes[0], node
