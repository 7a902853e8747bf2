"""What the Python front end hands on, read off the analysis of one group of modules.

The abstract interpreter's state — heap, effects, call record — is large and tied to one
analysis; the graph, the rules and launch analysis need only what is read from it: the
code-level nodes with their entities, the rclpy usage and message facts, the diagnostics,
the actions of the Python launch files, and where each Python executable leads.

The workspace is analysed in groups of modules that import nothing from one another
(:meth:`.Program.components`): a group's facts depend on its own files alone, so the facts
of a group nobody edited can be kept (:mod:`.facts_cache`) and the workspace's facts are
the groups' facts put together (:func:`merged`).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Sequence

from .absint.engine import Analysis
from .graph.builder import build_graph_from
from .graph.message_builder import message_facts
from .graph.messages import MessageFacts
from .graph.model import Diagnostic, RosNode, internal_error
from .graph.usage import UsageFacts, callback_order
from .launch.actions import Action
from .launch.discover import read_python_launches
from .launch.model import ExecutableRef
from .launch.packages import Executable
from .launch.targets import EntryReach, entry_key


@dataclass
class PythonFacts:
    """The Python front end's results for some modules (a group, or the whole workspace)."""

    nodes: list[RosNode] = field(default_factory=list)
    usage: UsageFacts = field(default_factory=UsageFacts)
    messages: MessageFacts = field(default_factory=lambda: MessageFacts([], [], [], [], []))
    diagnostics: list[Diagnostic] = field(default_factory=list)
    #: Python launch file path -> its actions, or why there are none.
    launches: dict[str, tuple[list[Action], str | None]] = field(default_factory=dict)
    #: :func:`.entry_key` of a Python executable -> the nodes it creates.
    targets: dict[str, ExecutableRef] = field(default_factory=dict)


def facts_of(analysis: Analysis, executables: Sequence[Executable]) -> PythonFacts:
    """The facts of a finished ``analysis``; ``executables``: the Python executables that run
    its modules. A defect in one kind of fact costs that kind only, with a diagnostic."""
    facts = PythonFacts()
    facts.diagnostics.extend(Diagnostic(m.path, 1, why) for m, why in analysis.program.rejected)
    facts.diagnostics.extend(Diagnostic(d.path, d.line, d.message, d.severity)
                             for d in analysis.diagnostics)
    graph = build_graph_from(analysis)
    facts.nodes = graph.nodes
    facts.usage = graph.usage if graph.usage is not None else UsageFacts()
    facts.diagnostics.extend(graph.diagnostics)
    try:
        facts.messages = message_facts(analysis)
    except Exception as exc:
        facts.diagnostics.append(internal_error("message facts not gathered", exc))
    facts.launches = read_python_launches(analysis)
    try:
        reach = EntryReach(analysis, executables)
        facts.targets = {entry_key(exe): reach.python_target(exe) for exe in executables}
    except Exception as exc:
        facts.diagnostics.append(internal_error("executables not tied to their nodes", exc))
    return facts


def merged(parts: Sequence[PythonFacts]) -> PythonFacts:
    """The facts of several groups as one: lists joined and put in the order the analysis of
    all of them at once would give."""
    out = PythonFacts()
    for part in parts:
        out.nodes += part.nodes
        for name in ("callbacks", "blocking", "parameter_uses", "redeclarations", "periods",
                     "out_of_order"):
            getattr(out.usage, name).extend(getattr(part.usage, name))
        out.usage.nodes.update(part.usage.nodes)
        out.usage.unattributed_parameters |= part.usage.unattributed_parameters
        for name in ("stores", "reads", "constructions", "publications", "service_returns"):
            getattr(out.messages, name).extend(getattr(part.messages, name))
        out.diagnostics += part.diagnostics
        out.launches.update(part.launches)
        out.targets.update(part.targets)
    out.nodes.sort(key=lambda n: (n.fqn or "", n.location))
    out.usage.callbacks.sort(key=callback_order)
    for name in ("stores", "reads", "constructions", "publications", "service_returns"):
        getattr(out.messages, name).sort(key=repr)
    return out
