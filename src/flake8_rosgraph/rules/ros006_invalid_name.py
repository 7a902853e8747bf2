"""ROS006 invalid-name."""
from __future__ import annotations

from typing import Iterator

from ..graph.model import RosGraph, RosNode
from .base import Finding, Rule, RuleConfig
from .vocabulary import NAME_NOUN


def _node_label(node: RosNode) -> str:
    """The node as written: ``ns/name`` when both are known, else whichever is."""
    if node.name is not None and node.namespace is not None:
        return node.namespace.rstrip("/") + "/" + node.name
    return node.name or node.namespace or "?"


class InvalidName(Rule):
    """## What it does
    Checks node names, namespaces, and topic, service, action and parameter
    names against the rules rcl and rmw enforce: allowed characters
    (`[A-Za-z0-9_]` and `/`), no leading digit in a component, no `//`, no
    trailing `/`, `~` only at the start and followed by `/`, balanced `{}`
    substitutions, and the length limits.

    ## Why is this bad?
    rclpy raises at run time (`InvalidNodeNameException`,
    `InvalidTopicNameException`, `InvalidServiceNameException`,
    `InvalidParameterException`, ...) when the node or entity is created, so
    the node crashes on start-up — often only in the configuration that builds
    the bad name.

    ## Known problems
    The check needs the name: a name the analysis cannot determine is not
    checked (see ROS010). Every possible value of a name is checked, so a
    name that is invalid only on one branch is reported too.

    ## Example
    ```python
    super().__init__('2nd-camera')
    self.create_publisher(Image, 'camera//image', 10)
    ```

    ## Use instead
    ```python
    super().__init__('second_camera')
    self.create_publisher(Image, 'camera/image', 10)
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
        for node in graph.nodes:
            if node.invalid:
                yield Finding(node.location, self.code, f"rcl rejects node '{_node_label(node)}': {node.invalid}")
            for entity in node.entities:
                if entity.invalid:
                    shown = entity.raw_name if entity.raw_name is not None else entity.name
                    message = f"rcl rejects {NAME_NOUN[entity.kind]} name '{shown}': {entity.invalid}"
                    yield Finding(entity.location, self.code, message)
