"""ROS010 unresolved-name."""
from __future__ import annotations

from typing import Iterator

from ..graph.model import NAMED_KINDS, RosGraph
from .base import Finding, Rule, RuleConfig
from .vocabulary import ENTITY_NOUN, NAME_NOUN


class UnresolvedName(Rule):
    """## What it does
    Reports every node and every publisher, subscription, service, client and
    action server/client whose name the analysis cannot determine statically.

    ## Why is this bad?
    It is not a bug in your code: it marks a blind spot of the analysis. The
    graph rules cannot judge an entity without a name, and an unresolved name
    also silences ROS001, ROS003, ROS008 and ROS009 for every entity it might
    connect to. Auditing these spots tells you how much of the graph the
    checks actually cover, and where a constant (or a stub file) would let
    them see more.

    ## Known problems
    Off by default (enable it with `--select ROS010` or
    `--extend-select ROS010`). Names that come from the command line, a
    launch file's remapping or a parameter set at run time are unresolved by
    design.

    ## Example
    ```python
    topic = sys.argv[1]
    self.create_publisher(String, topic, 10)
    ```

    ## Use instead
    ```python
    self.declare_parameter('topic', 'chatter')
    topic = self.get_parameter('topic').value   # default 'chatter' is used
    self.create_publisher(String, topic, 10)
    ```

    ## Options
    None.
    """

    code = "ROS010"
    name = "unresolved-name"
    level = "note"
    precision = "high"  # SARIF/code-scanning precision: how often a finding is a real problem
    summary = "the analysis cannot determine a name statically, so graph rules cannot judge that entity"
    default_enabled = False

    def check(self, graph: RosGraph, config: RuleConfig) -> Iterator[Finding]:
        for node in graph.nodes:
            if node.name is None:
                yield Finding(node.location, self.code, "node name cannot be determined statically")
            elif node.namespace is None:
                yield Finding(node.location, self.code,
                              f"namespace of node '{node.name}' cannot be determined statically")
            for entity in node.entities:
                if entity.kind in NAMED_KINDS and entity.name is None:
                    message = (f"{NAME_NOUN[entity.kind]} name of {ENTITY_NOUN[entity.kind]} "
                               f"cannot be determined statically")
                    if entity.name_text:
                        message += f": `{entity.name_text}`"
                    yield Finding(entity.location, self.code, message)
