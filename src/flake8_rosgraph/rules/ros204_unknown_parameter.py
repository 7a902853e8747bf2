"""ROS204 unknown-parameter."""
from __future__ import annotations

from typing import Iterator

from ..graph import names
from ..graph.model import Location, RosGraph
from ..launch.model import Instance, LaunchedNode, System
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
    Only Python nodes whose code is in the workspace are judged (C++ nodes
    may declare parameters through generated code), and a node that
    allows undeclared parameters (`allow_undeclared_parameters=True`) or
    declares one whose name the analysis cannot determine is skipped. A name
    written at a declaration call (`declare_parameter('can_bus', …)`) that the
    analysis did not tie to a known node — a plugin loaded by name, a builder
    chain it lost — may be declared on any node: it is not reported.
    `SetParameter` values (meant for every node of a scope) are not judged.
    rcl hands a process's parameters to every node it creates, so a value
    is reported only when no node of that process that receives it declares
    it (a multi-node executable is judged as one process). A value that one
    place (a shared dictionary, a file section) hands to several launched
    nodes is reported only when none of them declares it and all are
    judged; and launch actions that start one node name under conditions
    (the driver unless `use_fake_hardware`, its fake stand-in if it) share
    their parameters: a value a stand-in declares, or a stand-in that is
    not judged receives, is not reported on the other.
    A section with a wildcard (`/**:`, `*:`) is a configuration shared by
    every node it reaches — often read by the launch file or other tools
    too — so a value there is reported only when it is also a near miss of
    a parameter one of its receivers declares (`rte` beside `rate`).

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
        # Names written at declarations the analysis did not tie to a known node: some node
        # may declare them unseen (a builder chain it lost, a wrapper on an unknown receiver).
        unseen = graph.usage.unattributed_parameters if graph.usage is not None else frozenset()
        for system in graph.systems:
            yield from self._system(system, unseen)

    def _system(self, system: System, unseen: frozenset[str]) -> Iterator[Finding]:
        """rcl hands a process's parameters to every node it creates, and a launch file may hand
        one parameter source (a dict it shares, a file section) to several processes: a value is
        ignored only when no node that receives it from that place declares it, and that is known
        only when every such node is analysed and declares parameters of known names only."""
        processes: dict[int, list[Instance]] = {}
        for instance in system.instances:
            processes.setdefault(id(instance.launched), []).append(instance)
        excused: set[tuple[str, Location]] = set()  # reaches a node that may declare it unseen
        shared: set[tuple[str, Location]] = set()  # set in a wildcard section: near misses only
        receivers: dict[tuple[str, Location], list[Instance]] = {}
        declared: dict[int, set[str]] = {}
        # Conditional launch actions that start one node name are stand-ins for one another (the
        # real driver unless use_fake_hardware, the fake if it): a parameter of that name set on
        # one is meant for the role when a stand-in declares it or is not judged.
        role_names: dict[str, set[str]] = {}
        for launched in system.nodes:
            process = processes.get(id(launched), [])
            for role in _roles(launched, process):
                role_names.setdefault(role, set()).update(
                    _declared_names(process) if self._judged(launched, process)
                    else {n for n, _ in _received(system, launched, process)})
        for launched in system.nodes:
            process = processes.get(id(launched), [])
            if not self._judged(launched, process):
                excused.update(_received(system, launched, process))
                continue
            meant_for_role = set().union(*(role_names[role] for role in _roles(launched, process)))
            excused.update((n, loc) for i in process for n, _v, loc, _o in i.settings
                           if n in meant_for_role and n not in _declared_names(process))
            for instance in process:
                declared[id(instance)] = {e.name for e in instance.code.entities if e.kind == "parameters"}
                for name, _value, location, origin in instance.settings:
                    if origin == "scope" or name in BUILTIN_PARAMETERS or name.startswith(BUILTIN_PREFIXES):
                        continue
                    if origin == "shared file":
                        shared.add((name, location))
                    receivers.setdefault((name, location), []).append(instance)
        for (name, location), nodes in sorted(receivers.items(), key=lambda kv: (kv[0][1], kv[0][0])):
            if (name, location) in excused or name in unseen or any(name in declared[id(i)] for i in nodes):
                continue
            known = set().union(*(declared[id(i)] for i in nodes))
            close = sorted(k for k in known if k and names.edit_distance(k, name, 2) <= 2)
            if close or (name, location) not in shared:
                yield self._finding(name, location, nodes, close)

    @staticmethod
    def _judged(launched: LaunchedNode, process: list[Instance]) -> bool:
        """Whether what the launched executable's nodes declare is known: analysed code, no node
        open to any parameter, every declared name known."""
        return bool(process) and all(
            instance.analysed and instance.code.location not in launched.target.open_parameter_sites
            and all(e.name is not None for e in instance.code.entities if e.kind == "parameters")
            for instance in process)

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


def _received(system: System, launched: LaunchedNode, process: list[Instance]) -> set[tuple[str, Location]]:
    """The ``(name, location)`` of every value that reaches a launched node not judged here: its
    bound nodes' settings, else its inline values and the sections of its files that may match it
    (all of them when its name is not known)."""
    out = {(name, location) for instance in process for name, _value, location, _origin in instance.settings}
    if process:
        return out
    out.update((p.name, p.location) for p in launched.params)
    fqn = None if launched.name is None or launched.namespace is None or launched.unresolved \
        else names.fqn(launched.name, launched.namespace)
    for file in launched.param_files:
        for section in system.parameter_files.get(file.path or "", []):
            if fqn is None or section.matches(fqn):
                out.update((name, location) for name, _value, location in section.settings)
    return out


def _declared_names(process: list[Instance]) -> set[str]:
    return {e.name for i in process for e in i.code.entities if e.kind == "parameters" and e.name is not None}


def _roles(launched: LaunchedNode, process: list[Instance]) -> set[str]:
    """The node names a conditional launch action runs (its stand-ins share them)."""
    if not launched.conditional:
        return set()
    if process:
        return {i.node.fqn for i in process if i.node.fqn is not None}
    if launched.name is None or launched.unresolved:
        return set()
    return {names.fqn(launched.name, launched.namespace or "/")}
