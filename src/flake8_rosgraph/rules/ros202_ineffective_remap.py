"""ROS202 ineffective-remap."""
from __future__ import annotations

from typing import Iterator

from ..graph import names
from ..graph.model import RosGraph
from ..launch.model import Instance, Remap, System
from .base import Finding, Rule, RuleConfig

#: Names rcl uses on every node without the code asking for them; remapping them is legitimate.
_IMPLICIT = frozenset({"/rosout", "/parameter_events"})
#: The node's own services and topics under its private prefix (parameter services, type
#: description, lifecycle), created without the code naming them.
_IMPLICIT_PRIVATE = frozenset({
    "describe_parameters", "get_parameter_types", "get_parameters", "list_parameters",
    "set_parameters", "set_parameters_atomically", "get_type_description",
    "change_state", "get_state", "get_available_states", "get_available_transitions",
    "get_transition_graph", "transition_event"})


def _judgeable(instance: Instance, remap: Remap) -> bool:
    """Whether "matches nothing" is a fact: every name known, and not a special or implicit name."""
    node = instance.node
    if not instance.names_known or node.name is None or node.namespace is None:
        return False
    if remap.source.startswith("__"):
        return False  # __node, __ns, __log_level … are not topic remaps
    if any(remap.source == name or remap.source.startswith(name.rstrip("/") + "/")
           for name in instance.code.unseen_names):
        return False  # the node hands this name to a library the analysis cannot see into,
        # which may also derive names under it (``image_raw/filter_state``)
    expanded, _ = names.expand_topic_name(remap.source, node.name, node.namespace)
    if expanded is None:
        return False  # ROS203 reports an invalid source
    private = names.fqn(node.name, node.namespace) + "/"
    if expanded.startswith(private) and expanded[len(private):] in _IMPLICIT_PRIVATE:
        return False
    return expanded not in _IMPLICIT


class IneffectiveRemap(Rule):
    """## What it does
    Checks that every remapping rule in a launch file (a node's
    `remappings` / `<remap>`, or a `SetRemap` / `<set_remap>` of its scope)
    matches a topic, service or action name that the node uses. Names are
    compared as rcl compares them: both sides fully expanded in the node's
    final name and namespace.

    ## Why is this bad?
    A remap that matches nothing is silently ignored by rcl: the node keeps
    talking on its original name, and the connection the remap was meant to
    make does not exist — usually a typo in the source name, or a source
    written relative to a namespace the node does not run in.

    ## Known problems
    Only nodes whose code is in the workspace and whose every name is known
    are judged (a C++ node's names are not), and a source the node's class
    writes as an argument of a call that hands the node to an unmodelled
    library (`hbba_lite.OnOffHbbaSubscriber(self, Image, 'image_raw', ...)`)
    is taken as used, with the names under it: that library makes the end,
    and may derive more (`image_raw/filter_state`). A `SetRemap` is reported only
    when it matches no name of any node it applies to; likewise a node's own
    rule when its executable creates several nodes (rcl hands the process's
    rules to each of them). Remaps of the names
    rcl uses implicitly (`/rosout`, `/parameter_events`, a node's built-in
    parameter, logger and lifecycle services) and special rules (`__ns`,
    `__node`) are not judged; other private names (`~/status`) are. The
    message suggests a name the node uses within two edits of the source.

    ## Example
    ```python
    Node(package='demo_py', executable='listener', remappings=[('hear', 'chatter')])
    ```

    ## Use instead
    ```python
    Node(package='demo_py', executable='listener', remappings=[('heard', 'chatter')])
    ```

    ## Options
    None.
    """

    code = "ROS202"
    name = "ineffective-remap"
    level = "warning"
    precision = "high"  # SARIF/code-scanning precision: how often a finding is a real problem
    summary = "a remap rule's source matches no name that the node uses"

    def check(self, graph: RosGraph, config: RuleConfig) -> Iterator[Finding]:
        for system in graph.systems:
            yield from self._system(system)

    def _system(self, system: System) -> Iterator[Finding]:
        # A remap (by its position in a launched node's list) → the instances it applies to.
        scope_rules: dict[Remap, list[tuple[Instance, int]]] = {}
        # rcl hands a process's remap rules to every node it creates: a rule of one launch
        # action is effective when it matches a name of any of the executable's nodes.
        hits: dict[int, set[int]] = {}
        judged: dict[int, list[Instance]] = {}
        for instance in system.instances:
            hits.setdefault(id(instance.launched), set()).update(instance.remap_hits)
            judged.setdefault(id(instance.launched), []).append(instance)
        for instance in system.instances:
            # one finding per launch action, told on the node that uses the most names
            first = max(judged[id(instance.launched)], key=lambda inst: len(inst.expanded)) is instance
            for index, remap in enumerate(instance.launched.remaps):
                if remap.from_scope:
                    scope_rules.setdefault(remap, []).append((instance, index))
                elif first and index not in hits[id(instance.launched)] \
                        and all(_judgeable(inst, remap) for inst in judged[id(instance.launched)]):
                    yield self._finding(remap, instance)
        for remap, uses in scope_rules.items():
            if any(index in inst.remap_hits for inst, index in uses):
                continue
            judged = [inst for inst, _ in uses if _judgeable(inst, remap)]
            if judged and len(judged) == len(uses) and self._all_nodes_known(system, remap):
                yield self._finding(remap, judged[0], len(judged))

    @staticmethod
    def _all_nodes_known(system: System, remap: Remap) -> bool:
        """Every node the SetRemap reaches is analysed (none is C++ or unresolved)."""
        return all(node.target.status == "found" for node in system.nodes if remap in node.remaps)

    def _finding(self, remap: Remap, instance: Instance, count: int = 1) -> Finding:
        node = instance.node
        if count > 1:
            message = (f"remap '{remap.source}' -> '{remap.target}' matches no name used by "
                       f"any of the {count} nodes it applies to")
        else:
            used = instance.expanded
            shown = ", ".join(used[:4]) + (", …" if len(used) > 4 else "")
            message = (f"remap '{remap.source}' -> '{remap.target}' matches no name node "
                       f"'{node.fqn}' uses" + (f" (it uses {shown})" if used else ""))
            expanded, _ = names.expand_topic_name(remap.source, node.name or "", node.namespace or "/")
            close = [name for name in used if expanded and names.edit_distance(name, expanded, 2) <= 2]
            if close:
                message += f"; did you mean '{close[0]}'?"
        return Finding(remap.location, self.code, message, ((node.location, f"node '{node.fqn}'"),))
