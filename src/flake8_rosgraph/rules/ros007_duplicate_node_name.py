"""ROS007 duplicate-node-name."""
from __future__ import annotations

from collections import defaultdict
from typing import Iterator

from ..graph.model import Location, RosGraph
from .base import Finding, Rule, RuleConfig


class DuplicateNodeName(Rule):
    """## What it does
    Checks for two node creation sites in one source file that resolve to the
    same fully qualified node name.

    ## Why is this bad?
    ROS 2 does not enforce unique node names: both nodes start, but tools
    (`ros2 node`, `ros2 param`, lifecycle management, launch's event handlers)
    address nodes by name and then reach only one of them, or either at
    random, and the parameter services of the two collide.

    ## Known problems
    The rule must only compare nodes that can run together, and the graph
    does not yet record which executable or launch file starts which node.
    Nodes created in one file run in one process far more often than not, so
    the rule compares those only. Measured with the extractor on 15 public
    repositories with rclpy nodes (120 nodes): all 21 repetitions of a node
    name across files are alternative programs that never run together
    (tutorial variants such as `minimal_publisher` in three styles, Nav2's
    test programs all named `nav2_tester`); no name is created twice in one
    file. Alternatives of one creation site (`Node('a' if x else 'b')`) and
    nodes created by one call inside a loop are one site and do not
    count. The knob `DuplicateNodeName(across_files=True)` compares all
    files.

    ## Example
    ```python
    def main():
        rclpy.init()
        left = rclpy.create_node('camera')
        right = rclpy.create_node('camera')
    ```

    ## Use instead
    ```python
        left = rclpy.create_node('camera', namespace='left')
        right = rclpy.create_node('camera', namespace='right')
    ```

    ## Options
    None.
    """

    code = "ROS007"
    name = "duplicate-node-name"
    level = "warning"
    precision = "medium"  # SARIF/code-scanning precision: how often a finding is a real problem
    summary = "two nodes that can run together resolve to the same fully qualified name"

    def __init__(self, across_files: bool = False) -> None:
        #: Knob: also compare creation sites in different files (for workspaces whose files are one system).
        self.across_files = across_files

    def check(self, graph: RosGraph, config: RuleConfig) -> Iterator[Finding]:
        sites: dict[tuple[str, str], set[Location]] = defaultdict(set)
        for node in graph.nodes:
            if node.fqn is not None:
                scope = "" if self.across_files else node.location.path
                sites[(scope, node.fqn)].add(node.location)
        for (_, fqn), locations in sorted(sites.items()):
            first, *others = sorted(locations)
            for location in others:
                message = f"node '{fqn}' is also created at {first.short()}"
                yield Finding(location, self.code, message, ((first, f"node '{fqn}'"),))
