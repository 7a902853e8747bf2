"""ROS006 invalid-name."""
from __future__ import annotations

from typing import Iterator

from ..graph import names
from ..graph.model import Entity, Location, RosGraph, RosNode
from .base import Finding, Rule, RuleConfig
from .launch_context import in_package, packages_maybe_namespaced
from .vocabulary import NAME_NOUN
from .written import written_graph


def _node_label(node: RosNode) -> str:
    """The node as written: ``ns/name`` when both are known, else whichever is."""
    if node.name is not None and node.namespace is not None:
        return node.namespace.rstrip("/") + "/" + node.name
    return node.name or node.namespace or "?"


def _where_root(node: RosNode) -> str:
    """Who leaves the node in the root namespace: the launch file that starts it, or nobody."""
    if node.launch is not None:
        return f" as {node.launch.get('file')} starts it"
    return " when nothing sets one"


def disabled_when_empty(entity: Entity) -> bool:
    """Whether the name is a parameter that defaults to the empty string, on an end the code
    creates only under a condition: the idiom "empty = disabled" (``if self.track_topic:
    self.create_subscription(…, self.track_topic, …)``). The analysis does not narrow the
    parameter's value by the condition, so the empty default reaching the call says nothing."""
    return entity.conditional and entity.name == "" and bool(entity.name_template) \
        and all(parameter and default == "" for parameter, default in entity.name_template)


class InvalidName(Rule):
    """## What it does
    Checks node names, namespaces, and topic, service, action and parameter
    names against the rules rcl and rmw enforce: allowed characters
    (`[A-Za-z0-9_]` and `/`), no leading digit in a component, no `//`, no
    trailing `/`, `~` only at the start and followed by `/`, balanced `{}`
    substitutions, and the length limits.

    Names built from the node's own namespace are evaluated in the namespace
    the node runs in: `self.get_namespace()` is the constructor's namespace,
    made absolute, and the root namespace `/` when nothing sets one — so
    `self.get_namespace() + '/cmd'` is `//cmd`, which rcl rejects. A node that
    launch files start is judged in each launch file's namespace, and the
    message says which one leaves it at the root. The safe spellings
    (`f"{ns.rstrip('/')}/cmd"`, `ns if ns != '/' else ''`, a relative name
    `'cmd'`) stay quiet.

    ## Why is this bad?
    rclpy raises at run time (`InvalidNodeNameException`,
    `InvalidTopicNameException`, `InvalidServiceNameException`,
    `InvalidParameterException`, ...) when the node or entity is created, so
    the node crashes on start-up — often only in the configuration that builds
    the bad name.

    ## Known problems
    The check needs the name: a name the analysis cannot determine is not
    checked (see ROS010). A launched node is judged with the names the launch
    file gives it, and also as written (`ros2 run`): a parameter's default in
    code that the launch file's value replaces is reported when rcl rejects it. Every possible value of a name is checked, so a
    name that is invalid only on one branch is reported too. A namespace
    passed with `--ros-args -r __ns:=…` outside launch files is not seen: a
    node started that way in a namespace is still judged at the root. Under a
    launch file's namespace, only a name that starts with the root's `//`
    is rebuilt in that namespace; a namespace the launch file computes in a
    way the analysis cannot follow makes such names unknown (not checked). An
    empty name taken from a parameter that defaults to `''`, on an end created
    under a condition, is the idiom "empty = disabled" (`if topic: create_…`)
    and is not reported: the analysis does not narrow the value by the
    condition. When
    a launch file starts an executable of the node's package that the analysis
    cannot match to code (built from a launch argument) in a namespace, the node
    may be that one: its namespace-built names are not judged at the root then.

    ## Example
    ```python
    super().__init__('2nd-camera')
    self.create_publisher(Image, 'camera//image', 10)
    self.create_publisher(Twist, self.get_namespace() + '/cmd_vel', 10)  # '//cmd_vel' at the root
    ```

    ## Use instead
    ```python
    super().__init__('second_camera')
    self.create_publisher(Image, 'camera/image', 10)
    self.create_publisher(Twist, 'cmd_vel', 10)  # relative: expanded in the node's namespace
    ```

    ## Options
    None.
    """

    code = "ROS006"
    name = "invalid-name"
    level = "error"
    precision = "very-high"  # SARIF/code-scanning precision: how often a finding is a real problem
    summary = "a node, namespace, topic, service, action or parameter name breaks the rcl/rmw validation rules"

    def check(self, graph: RosGraph, config: RuleConfig) -> Iterator[Finding]:
        namespaced = packages_maybe_namespaced(graph)
        reported: set[Location] = set()
        for node in graph.nodes:
            if node.invalid:
                yield Finding(node.location, self.code, f"rcl rejects node '{_node_label(node)}': {node.invalid}")
            for entity in node.entities:
                if entity.invalid and not disabled_when_empty(entity):
                    shown = entity.raw_name if entity.raw_name is not None else entity.name
                    message = f"rcl rejects {NAME_NOUN[entity.kind]} name '{shown}': {entity.invalid}"
                    if names.built_at_root(entity.raw_name, node.namespace):
                        if node.launch is None and in_package(node, namespaced):
                            continue  # a launch file may start it in a namespace: the root is a guess
                        message += (" (built from the node's namespace, which is the root namespace '/'"
                                    f"{_where_root(node)}: ns + '/x' gives '//x')")
                    reported.add(entity.location)
                    yield Finding(entity.location, self.code, message)
        yield from _as_written(graph, reported)


def _as_written(graph: RosGraph, reported: set[Location]) -> Iterator[Finding]:
    """Names rcl rejects when a launched node runs as written (``ros2 run``): a parameter's
    default in code that the launch file's value replaces (a space slipped into the default
    topic crashes the node started without that launch file)."""
    written = written_graph(graph)
    for node in written.nodes if written is not None else ():
        for entity in node.entities:
            if entity.invalid and entity.location not in reported and not disabled_when_empty(entity) \
                    and not names.built_at_root(entity.raw_name, node.namespace):
                reported.add(entity.location)
                shown = entity.raw_name if entity.raw_name is not None else entity.name
                yield Finding(entity.location, InvalidName.code,
                              f"rcl rejects {NAME_NOUN[entity.kind]} name '{shown}' when the node runs as "
                              f"written (`ros2 run`), without the launch file's value: {entity.invalid}")

