"""ROS204 unknown-parameter."""
from __future__ import annotations

from typing import Iterator

from ..graph import names
from ..graph.model import RosGraph
from ..launch.model import Instance
from .base import Finding, Rule, RuleConfig

#: Parameters rclpy declares on every node by itself.
BUILTIN_PARAMETERS = frozenset({"use_sim_time", "start_type_description_service"})
BUILTIN_PREFIXES = ("qos_overrides.",)


class UnknownParameter(Rule):
    """## What it does
    Checks that every parameter a launch file sets for a node — inline
    (`parameters=[{...}]`, `<param name= value=>`) or in a parameter YAML
    file section that matches the node (`/**`, `node_name`, `/ns/node_name`)
    — is declared by that node's code.

    ## Why is this bad?
    rclpy ignores a parameter override nobody declares (unless the node
    allows undeclared parameters): the node runs with its default, and the
    value in the file — often a typo of the real name — has no effect.

    ## Known problems
    Only nodes whose code is in the workspace are judged, and a node that
    allows undeclared parameters (`allow_undeclared_parameters=True`) or
    declares one whose name the analysis cannot determine is skipped.
    `SetParameter` values (meant for every node of a scope) are not judged.

    ## Example
    ```yaml
    /**:
      ros__parameters:
        rte: 5.0
    ```

    ## Use instead
    ```yaml
    /**:
      ros__parameters:
        rate: 5.0
    ```

    ## Options
    None.
    """

    code = "ROS204"
    name = "unknown-parameter"
    level = "warning"
    precision = "high"  # SARIF/code-scanning precision: how often a finding is a real problem
    summary = "a launch file or parameter YAML sets a parameter the node never declares"

    def check(self, graph: RosGraph, config: RuleConfig) -> Iterator[Finding]:
        for system in graph.systems:
            for instance in system.instances:
                yield from self._instance(instance)

    def _instance(self, instance: Instance) -> Iterator[Finding]:
        if instance.code.location in instance.launched.target.open_parameter_sites:
            return
        declared = [e.name for e in instance.code.entities if e.kind == "parameters"]
        if any(name is None for name in declared):
            return
        known = set(declared)
        node = instance.node
        for name, _value, location, origin in instance.settings:
            if origin == "scope" or name in known or name in BUILTIN_PARAMETERS \
                    or name.startswith(BUILTIN_PREFIXES):
                continue
            message = f"parameter '{name}' is set for node '{node.fqn}', which never declares it"
            close = sorted(k for k in known if k and names.edit_distance(k, name, 2) <= 2)
            if close:
                message += f"; did you mean '{close[0]}'?"
            yield Finding(location, self.code, message, ((node.location, f"node '{node.fqn}'"),))
