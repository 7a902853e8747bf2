"""ROS203 invalid-launch-name."""
from __future__ import annotations

from typing import Iterator

from ..graph import names
from ..graph.model import RosGraph
from .base import Finding, Rule, RuleConfig


class InvalidLaunchName(Rule):
    """## What it does
    Checks the names a launch file gives: a node's `name`, its namespace
    (after pushed namespaces are prefixed), and both sides of every
    remapping rule, against the rules rcl and rmw enforce (allowed
    characters, no leading digit in a token, no `//`, no trailing `/`, `~`
    and `{}` placement, length limits).

    ## Why is this bad?
    rcl rejects the `--ros-args` launch builds from them: the node exits on
    start-up ("Invalid node name", "Failed to parse remap rule"), so the
    system comes up without it.

    ## Known problems
    Only names the launch file determines statically are checked; a name
    from a launch argument without a default is not. Names in the code are
    ROS006's.

    ## Example
    ```xml
    <node pkg="demo_cpp" exec="relay" name="relay-1" namespace="robot/"/>
    ```

    ## Use instead
    ```xml
    <node pkg="demo_cpp" exec="relay" name="relay_1" namespace="robot"/>
    ```

    ## Options
    None.
    """

    code = "ROS203"
    name = "invalid-launch-name"
    level = "error"
    precision = "very-high"  # SARIF/code-scanning precision: how often a finding is a real problem
    summary = "a node name, namespace or remap target in a launch file breaks the rcl rules"

    def check(self, graph: RosGraph, config: RuleConfig) -> Iterator[Finding]:
        for system in graph.systems:
            for node in system.nodes:
                if node.name is not None:
                    check = names.validate_node_name(node.name)
                    if not check.ok:
                        yield Finding(node.location, self.code,
                                      f"rcl rejects node name '{node.name}': {check.reason}")
                if node.namespace is not None:
                    check = names.validate_namespace(node.namespace)
                    if not check.ok:
                        yield Finding(node.location, self.code,
                                      f"rcl rejects namespace '{node.namespace}': {check.reason}")
                for remap in node.remaps:
                    for side, value in (("source", remap.source), ("target", remap.target)):
                        if value.startswith("__"):
                            continue
                        check = names.validate_topic_name(value)
                        if not check.ok:
                            yield Finding(remap.location, self.code,
                                          f"rcl rejects remap {side} '{value}': {check.reason}")
