"""ROS204 unknown-parameter."""
from __future__ import annotations

from typing import Iterator

from ..graph import names
from ..graph.model import Location, RosGraph
from ..launch.model import Instance, System
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
    rcl hands a process's parameters to every node it creates, so a value
    is reported only when no node of that process that receives it declares
    it (a multi-node executable is judged as one process).
    A section with a wildcard (`/**:`, `*:`) is a configuration shared by
    every node it reaches — often read by the launch file or other tools
    too — so a value there is reported only when none of the nodes of the
    launch file that receive it declares it *and* it is a near miss of a
    parameter one of them declares (`rte` beside `rate`).

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
            processes: dict[int, list[Instance]] = {}
            for instance in system.instances:
                processes.setdefault(id(instance.launched), []).append(instance)
            declared = {id(i): _declared(i) for i in system.instances}
            unseen = _unseen_receivers(system)
            for process in processes.values():
                yield from self._judge(process, declared, unseen, shared=False)
            yield from self._judge(system.instances, declared, unseen, shared=True)

    def _judge(self, instances: list[Instance], declared: dict[int, set[str] | None],
               unseen: set[Location], shared: bool) -> Iterator[Finding]:
        """The settings that reach ``instances`` and that none of them declares.

        Without ``shared``: one launched executable, whose node-specific settings (inline,
        a section naming the node) rcl hands to every node it creates.  With ``shared``:
        the settings of wildcard sections, across the launch file, reported only as near
        misses."""
        receivers: dict[tuple[str, Location], list[Instance]] = {}
        for instance in instances:
            for name, _value, location, origin in instance.settings:
                if origin == "scope" or (origin == "shared file") != shared \
                        or name in BUILTIN_PARAMETERS or name.startswith(BUILTIN_PREFIXES):
                    continue
                receivers.setdefault((name, location), []).append(instance)
        for (name, location), nodes in sorted(receivers.items(), key=lambda kv: (kv[0][1], kv[0][0])):
            known = [declared[id(i)] for i in nodes]
            if location in unseen or any(k is None or name in k for k in known):
                continue  # a receiver may declare it (or allows undeclared parameters)
            close = sorted(k for k in set().union(*known) if k and names.edit_distance(k, name, 2) <= 2)
            if close or not shared:
                yield self._finding(name, location, nodes, close)

    def _finding(self, name: str, location: Location, nodes: list[Instance],
                 close: list[str]) -> Finding:
        fqns = sorted({i.node.fqn or "?" for i in nodes})
        target = f"node '{fqns[0]}', which never declares it" if len(fqns) == 1 else \
            "nodes " + ", ".join(f"'{f}'" for f in fqns) + ", none of which declares it"
        message = f"parameter '{name}' is set for {target}"
        if close:
            message += f"; did you mean '{close[0]}'?"
        related = tuple(sorted({(i.node.location, f"node '{i.node.fqn}'") for i in nodes}))
        return Finding(location, self.code, message, related)


def _unseen_receivers(system: System) -> set[Location]:
    """Where settings are written that also reach a launched node whose code is not analysed
    (C++, another workspace): the value may be meant for that node."""
    bound = {id(i.launched) for i in system.instances}
    out: set[Location] = set()
    for launched in system.nodes:
        if id(launched) in bound:
            continue
        out.update(p.location for p in launched.params)
        fqn = None if launched.name is None or launched.namespace is None else \
            launched.namespace.rstrip("/") + "/" + launched.name
        for file in launched.param_files:
            for section in system.parameter_files.get(file.path or "", []):
                if fqn is None or section.matches(fqn):
                    out.update(location for _, _, location in section.settings)
    return out


def _declared(instance: Instance) -> set[str] | None:
    """The parameters the node's code declares; ``None`` when any name may be accepted (it
    allows undeclared parameters, or declares one whose name is unknown)."""
    names_ = [e.name for e in instance.code.entities if e.kind == "parameters"]
    if instance.code.location in instance.launched.target.open_parameter_sites \
            or any(name is None for name in names_):
        return None
    return set(names_)
