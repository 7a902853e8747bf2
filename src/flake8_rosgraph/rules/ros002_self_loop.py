"""ROS002 self-loop."""
from __future__ import annotations

from collections import defaultdict
from typing import Iterator

from ..graph.model import Entity, Location, RosGraph, RosNode
from .base import Finding, Rule, RuleConfig
from .exempt import ExemptNames
from .fixtures import node_scope
from .launch_context import in_package, launched_in_namespace, packages_maybe_namespaced
from .vocabulary import related


class SelfLoop(Rule):
    """## What it does
    Checks for nodes that subscribe to a topic they also publish (the red
    "loop" edge of the thesis graphs).

    ## Why is this bad?
    The node receives every message it sends, through the middleware: its
    callback runs on its own output, which can feed back without end, doubles
    the processing of every message, and usually means that the subscription
    was meant for a different topic (an input named like the output) or that
    the data should be passed by a direct method call.

    ## Known problems
    Some loops are deliberate (a node that watches its own output for
    monitoring, or a relay that republishes). Exempt names are not reported:
    a node that broadcasts transforms and also listens to `/tf` through a tf2
    `TransformListener` is normal. The rule compares resolved names only; an unresolved name never
    makes a loop, nor does one rclpy rejects (ROS006: that end never exists), nor a name known only partly (`param if launched else '/scan'`). A node that launch files start in a namespace (one per robot)
    and that publishes and subscribes an absolute name is not reported: the
    absolute name is a bus its instances share on purpose (a swarm's votes),
    and each instance hears the others. A topic that two or more nodes of different names,
    made at different places, each publish and subscribe with one type is a channel they share on purpose
    (each stage of a pipeline announces its state and follows the others'): it
    is not reported for any of them. A node class instantiated by several executables that each
    add entities from their own module (a reader executable publishing what a
    parser executable subscribes to, on one driver class) is not a loop: ends
    created in two files other than the node's own (the file that creates it,
    or that defines its class when a base class creates it) are not compared.
    A test fixture (a node created in a test module or under `test/`, as for
    ROS001) that publishes and subscribes one topic with one type is a test
    harness checking that its message goes through (or recording what the
    system under test also hears), not a loop; a fixture whose subscription
    has another type than its publisher on the name is still reported.
    A production node that publishes and subscribes one topic to hear the
    other instances of itself (`ros2 doctor hello`, whose callback drops its
    own messages by host name) is reported: the graph holds nothing that tells
    it from a loop by mistake (both ends then have the same name and type, and
    a single variable naming both is also how a copy-paste slip looks). List
    such a topic in `--rosgraph-external-topics`.

    ## Example
    ```python
    class Filter(Node):
        def __init__(self):
            super().__init__('filter')
            self.pub = self.create_publisher(Imu, 'imu', 10)
            self.create_subscription(Imu, 'imu', self.on_imu, 10)
    ```

    ## Use instead
    ```python
            self.pub = self.create_publisher(Imu, 'imu/filtered', 10)
            self.create_subscription(Imu, 'imu/raw', self.on_imu, 10)
    ```

    ## Options
    - `--rosgraph-external-topics` (`ROSGRAPH_EXTERNAL_TOPICS`): names listed
      there are not reported either.
    """

    code = "ROS002"
    name = "self-loop"
    level = "warning"
    precision = "high"  # SARIF/code-scanning precision: how often a finding is a real problem
    summary = "a node subscribes to a topic that it also publishes"

    def check(self, graph: RosGraph, config: RuleConfig) -> Iterator[Finding]:
        exempt = ExemptNames.build(config.external_names)
        namespaced = packages_maybe_namespaced(graph)
        buses = _shared_buses(graph)
        for node in graph.nodes:
            instances = launched_in_namespace(node) or (node.launch is None and in_package(node, namespaced))
            harness = node_scope(node) is not None
            published: dict[str, list[Entity]] = defaultdict(list)
            for pub in node.of_kind("publishers"):
                # a partly known name (``param if launched else '/scan'``) is no evidence of a loop
                if pub.name is not None and pub.name not in exempt and not pub.partial and pub.invalid is None:
                    published[pub.name].append(pub)
            for sub in node.of_kind("subscriptions"):
                if sub.name not in published or sub.partial or sub.invalid is not None:
                    continue
                if instances and _absolute(sub) and all(_absolute(p) for p in published[sub.name]):
                    continue  # one bus shared by the instances in their namespaces: each hears the others
                if sub.name in buses and all(_same_type(p, sub) for p in published[sub.name]):
                    continue  # several nodes talk and listen on it: each hears the others
                pubs = sorted((p for p in published[sub.name] if _same_program(node, p, sub)
                               and not (harness and _same_type(p, sub))), key=lambda e: e.location)
                if pubs:
                    message = (f"node '{node.fqn or '?'}' subscribes to topic '{sub.name}' that it publishes "
                               f"at {pubs[0].location.short()}")
                    yield Finding(sub.location, self.code, message, tuple(related(p) for p in pubs))


def _shared_buses(graph: RosGraph) -> frozenset[str]:
    """The topics that two or more nodes of different names each publish and subscribe, with
    one type.

    A state or heartbeat channel (``/llm_state``: each stage of a pipeline announces its state
    and listens for the others') is a bus the nodes share on purpose: each one's subscription
    is there to hear the other publishers. A subscription renamed by mistake to a node's own
    output makes a loop on one node only, or one of another type. Nodes of one name, or made
    at one place (one program under two names), or of an unknown name are alternatives or
    instances of one program, not several members; a test fixture is a system of its own (a
    harness hearing its own command), no member of the production bus.
    """
    looping: dict[str, set[str]] = defaultdict(set)
    sites: dict[str, set[Location]] = defaultdict(set)
    types: dict[str, set[str]] = defaultdict(set)
    for node in graph.nodes:
        if node_scope(node) is not None or node.fqn is None:
            continue  # an unknown name may be the same node's
        published = {p.name: p for p in node.of_kind("publishers") if p.name is not None and not p.partial}
        for sub in node.of_kind("subscriptions"):
            pub = published.get(sub.name)
            if pub is not None and not sub.partial and _same_type(pub, sub):
                looping[sub.name].add(node.fqn)
                sites[sub.name].add(node.location)
                types[sub.name].update(t for t in (pub.type, sub.type) if t is not None)
    return frozenset(name for name, nodes in looping.items()
                     if len(nodes) > 1 and len(sites[name]) > 1 and len(types[name]) <= 1)


def _absolute(entity: Entity) -> bool:
    """Whether the name is written absolute (``/swarm/votes``): it escapes the node's namespace."""
    return (entity.raw_name or "").startswith("/")


def _same_type(pub: Entity, sub: Entity) -> bool:
    """Whether the two ends may carry one message type (an unknown type may).

    A test harness publishes a command and listens on the same topic to see
    it go through the middleware (or to record what the system under test
    also hears): both ends then have the topic's one type. A probe pointed by
    mistake at the harness's own stimulus almost always has another type.
    """
    return pub.type is None or sub.type is None or pub.type == sub.type


def _same_program(node: RosNode, pub: Entity, sub: Entity) -> bool:
    """Whether ``pub`` and ``sub`` can belong to one running instance of ``node``.

    A node class may be instantiated by several executables, each adding its
    own entities from its own module (nmea_navsat_driver's serial reader
    publishes ``nmea_sentence`` and its topic driver subscribes to it, both on
    one ``Ros2NMEADriver`` class): two ends created in two different files,
    neither of them the node's own (the file that creates it, or that defines
    its class: a subclass whose base calls ``super().__init__``), are not a loop.
    """
    files = {pub.location.path, sub.location.path}
    return len(files) == 1 or node.location.path in files or node.cls_path in files
