"""The ROS command-line arguments a node runs with: its own ``cli_args`` and its process's.

rcl gives a node the ``--ros-args`` of its ``cli_args`` and, unless it is created with
``use_global_arguments=False``, those its context was initialised with
(``rclpy.init(args=[…])``). The node's own come first: a local ``__ns``/``__node`` wins
and local remapping rules are tried before global ones (rcl/src/rcl/remap.c,
``rcl_remap_name``). Which nodes an ``rclpy.init`` concerns is a matter of processes,
which code does not spell out; here they are the nodes created by what the function
calling ``rclpy.init`` calls, transitively (the entry point starting the process). A node
reached from two inits that disagree gets neither's arguments: unknown beats wrong.
"""
from __future__ import annotations

from dataclasses import dataclass

from ..absint.callgraph import CallGraph
from ..absint.engine import Analysis, Effect
from ..absint.values import Seq, Value
from . import names


@dataclass(frozen=True)
class CommandLine:
    """What a node's ``cli_args`` set: ``__node:=``/``__ns:=`` and remapping rules.

    ``unsure``: a ``--ros-args`` word the analysis cannot read, which may set the name or the
    namespace; either is then the node's own business, whatever a launch file says."""

    name: str | None = None
    namespace: str | None = None
    remaps: tuple[names.RemapRule, ...] = ()
    unsure: bool = False

    @property
    def overrides(self) -> tuple[str, ...]:
        """The node properties these arguments (may) set (``"name"``, ``"namespace"``)."""
        return tuple(k for k, v in (("name", self.name), ("namespace", self.namespace))
                     if v is not None or self.unsure)


#: ROS arguments that take a value which is not a remapping (skipped with it).
_VALUED_ROS_ARGS = frozenset({"-p", "--param", "--params-file", "--log-level", "-e", "--enclave",
                              "--log-config-file"})


def command_line(value: Value) -> CommandLine:
    """The ``--ros-args`` of a node's ``cli_args``, when they are one list (an unknown list
    changes nothing: it is almost always empty in practice, and guessing would cost every
    name of the node). A word it cannot read makes the rest :attr:`CommandLine.unsure`."""
    seqs = [a for a in value if isinstance(a, Seq)] if not value.is_top else []
    if len(seqs) != 1 or len(list(value)) != 1:
        return CommandLine()
    words = [item.strings() for item in seqs[0].items]
    name = namespace = None
    remaps: list[names.RemapRule] = []
    inside, skip_next, rule_next = False, False, False
    for choices in words:
        word = choices[0] if choices is not None and len(choices) == 1 else None
        if word is None:
            if inside and not skip_next:
                return CommandLine(name, namespace, tuple(remaps), unsure=True)
            skip_next = False
            continue
        if word == "--ros-args":
            inside = True
        elif word == "--":
            inside = False
        elif not inside:
            continue
        elif skip_next:
            skip_next = False
        elif word in ("-r", "--remap"):
            rule_next = True
        elif word in _VALUED_ROS_ARGS:
            skip_next = True
        elif rule_next and ":=" in word:
            rule_next = False
            source, _, target = word.partition(":=")
            node, _, source = source.rpartition(":") if ":" in source else (None, "", source)
            if source == "__ns" and not node:
                namespace = target
            elif source in ("__node", "__name") and not node:
                name = target
            else:
                remaps.append(names.RemapRule(source, target, node or None))
    return CommandLine(name, namespace, tuple(remaps))


def with_process(own: CommandLine, process: CommandLine | None) -> CommandLine:
    """A node's own arguments over its process's (rcl's order: local, then global)."""
    if process is None:
        return own
    return CommandLine(own.name or process.name, own.namespace or process.namespace,
                       own.remaps + process.remaps, own.unsure or process.unsure)


def process_command_lines(analysis: Analysis) -> dict[Effect, CommandLine]:
    """The process-wide ``--ros-args`` of each ``node`` effect on the default context that
    takes global arguments, where every ``rclpy.init`` reaching its creation passed the same
    known ones (see the module docstring)."""
    inits = [(task, command_line(eff.arg("args")))
             for task, effects in analysis.effects.items() for eff in effects.values()
             if eff.kind == "context_init" and eff.arg("context").consts() == [None]]
    if all(line == CommandLine() for _, line in inits):
        return {}
    calls = analysis.call_graph()
    found: dict[Effect, set[CommandLine]] = {}
    for task, line in inits:
        for reached in _reachable(calls, task):
            for eff in analysis.effects.get(reached, {}).values():
                if eff.kind == "node" and eff.arg("context").consts() == [None] \
                        and eff.arg("use_global_arguments").consts() != [False]:
                    found.setdefault(eff, set()).add(line)
    return {eff: lines.pop() for eff, lines in found.items()
            if len(lines) == 1 and lines != {CommandLine()}}


def _reachable(calls: CallGraph, start: tuple) -> set[tuple]:
    """``start`` and every task its calls reach, transitively."""
    seen = {start}
    todo = [start]
    while todo:
        for site in calls.sites(todo.pop()):
            if site.callee[0] == "task" and site.callee[1] not in seen:
                seen.add(site.callee[1])
                todo.append(site.callee[1])
    return seen
