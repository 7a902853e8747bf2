"""ROS204 unknown-parameter."""
from __future__ import annotations

from typing import Iterator

from ..graph import names
from ..graph.model import Location, RosGraph
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
    rcl hands a process's parameters to every node it creates, and one
    parameter file section (`/**`) may reach the nodes of several launched
    processes, so a value is reported only when no node that receives it
    declares it (a multi-node executable is judged as one process; a common
    parameter file shared by several nodes, each reading its own part, is
    quiet).

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
            yield from self._system(system.instances)

    def _system(self, instances: list[Instance]) -> Iterator[Finding]:
        """One launch system. rcl hands a process's parameters to every node it creates, and
        one parameter file section (``/**``) may reach the nodes of several processes: a value
        is ignored only when no node it reaches declares it, and is not judged when one of
        them declares names the analysis cannot read."""
        processes: dict[int, list[Instance]] = {}
        for instance in instances:
            processes.setdefault(id(instance.launched), []).append(instance)
        declared: dict[int, set[str]] = {}
        open_: set[int] = set()
        for process in processes.values():
            for instance in process:
                names_ = [e.name for e in instance.code.entities if e.kind == "parameters"]
                if instance.code.location in instance.launched.target.open_parameter_sites \
                        or any(name is None for name in names_):
                    open_.update(id(i) for i in process)
                declared[id(instance)] = {name for name in names_ if name is not None}
        receivers: dict[tuple[str, Location], list[Instance]] = {}
        for instance in instances:
            for name, _value, location, origin in instance.settings:
                if origin == "scope" or name in BUILTIN_PARAMETERS \
                        or name.startswith(BUILTIN_PREFIXES):
                    continue
                receivers.setdefault((name, location), []).append(instance)
        for (name, location), nodes in sorted(receivers.items(), key=lambda kv: (kv[0][1], kv[0][0])):
            if any(id(i) in open_ or name in declared[id(i)] for i in nodes):
                continue
            yield self._finding(name, location, nodes, set().union(*(declared[id(i)] for i in nodes)))

    def _finding(self, name: str, location: Location, nodes: list[Instance],
                 known: set[str]) -> Finding:
        fqns = sorted({i.node.fqn or "?" for i in nodes})
        target = f"node '{fqns[0]}', which never declares it" if len(fqns) == 1 else \
            "nodes " + ", ".join(f"'{f}'" for f in fqns) + ", none of which declares it"
        message = f"parameter '{name}' is set for {target}"
        close = sorted(k for k in known if k and names.edit_distance(k, name, 2) <= 2)
        if close:
            message += f"; did you mean '{close[0]}'?"
        related = tuple(sorted({(i.node.location, f"node '{i.node.fqn}'") for i in nodes}))
        return Finding(location, self.code, message, related)
