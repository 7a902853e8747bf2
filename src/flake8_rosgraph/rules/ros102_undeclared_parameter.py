"""ROS102 undeclared-parameter."""
from __future__ import annotations

from typing import Iterator

from ..graph import names
from ..graph.model import RosGraph
from ..graph.usage import NodeParameters, ParameterUse
from .base import Finding, Rule, RuleConfig
from .ros204_unknown_parameter import BUILTIN_PARAMETERS, BUILTIN_PREFIXES

#: What each way of using an undeclared parameter does at run time.
CONSEQUENCE = {
    "get_parameter": "raises ParameterNotDeclaredException",
    "get_parameters": "raises ParameterNotDeclaredException",
    "set_parameters": "raises ParameterNotDeclaredException",
    "get_parameter_or": "always returns the alternative value",
}


def _misspelt(name: str, close: list[str]) -> bool:
    """Whether ``name`` reads as a slip of one of the ``close`` declared names: one edit away,
    and not a name of its own that merely shares a stem (``speed_2`` beside ``speed_1``)."""
    return any(names.edit_distance(declared, name, 1) <= 1 and not _numbered_sibling(declared, name)
               for declared in close)


def _numbered_sibling(a: str, b: str) -> bool:
    return a.rstrip("0123456789") == b.rstrip("0123456789") and a != b


class UndeclaredParameter(Rule):
    """## What it does
    Checks that every parameter a node reads with `get_parameter()`,
    `get_parameters()` or `get_parameter_or()`, or sets with `set_parameters()`,
    is declared on that node object on some path — in its class, a base class
    in another module, or any code that gets the node. Also reports a parameter
    declared twice on one node in one run (two `declare_parameter()` calls
    with the same name that both run whenever the body runs, directly or
    through calls).

    ## Why is this bad?
    Unless the node allows undeclared parameters, rclpy raises
    `ParameterNotDeclaredException` when code reads or sets a parameter it
    never declared (`get_parameter_or()` silently returns its alternative value
    forever), and `ParameterAlreadyDeclaredException` when a name is declared
    twice. Both surface at run time, often in a rarely taken branch.

    ## Known problems
    Nodes created with `allow_undeclared_parameters=True` or
    `automatically_declare_parameters_from_overrides=True` (or an unknown value
    for either) are skipped. On a node that declares a parameter whose name the
    analysis cannot determine (that one may be any name), only a read one
    letter off a name the node declares is reported, as a misspelling of it (not
    a numbered sibling: `step_height_2` beside `step_height_1`). A use on an
    object that is not known to be a node, or of a name that is not known, is
    skipped. Parameters rclpy declares itself
    (`use_sim_time`, `qos_overrides.*`, ...) count as declared. A read or set
    inside a `try` whose `except` clause may catch `ParameterNotDeclaredException`
    (it, `ParameterException`, `Exception`, a bare `except:`, or a class the
    analysis cannot name) is handled, not a bug; only a `try` in the calling
    function itself counts, and a test that provokes the exception inside
    `pytest.raises(...)` or `assertRaises(...)` is not recognised. Otherwise
    test code is judged like the product: a test whose node reads a parameter
    it never declares fails with the exception. A declaration
    repeated by a loop is not detected, only two declarations on one path; one
    inside a `try` or an `if` is never counted as a repeat, nor are two on a node
    object the analysis knows only as one of several nodes (many connectors built
    through one factory, merged by its bound on calling contexts): they may be on
    two nodes.

    ## Example
    ```python
    class Driver(Node):
        def __init__(self):
            super().__init__('driver')
            self.declare_parameter('port', '/dev/ttyUSB0')
            self.baud = self.get_parameter('baudrate').value
    ```

    ## Use instead
    ```python
    class Driver(Node):
        def __init__(self):
            super().__init__('driver')
            self.declare_parameter('port', '/dev/ttyUSB0')
            self.declare_parameter('baudrate', 115200)
            self.baud = self.get_parameter('baudrate').value
    ```

    ## Options
    None.
    """

    code = "ROS102"
    name = "undeclared-parameter"
    level = "error"
    precision = "high"
    summary = "a node reads or sets a parameter it never declares, or declares one twice"

    def check(self, graph: RosGraph, config: RuleConfig) -> Iterator[Finding]:
        usage = graph.usage
        if usage is None:
            return
        for use in usage.parameter_uses:
            yield from self._use(use, usage.nodes)
        for again in usage.redeclarations:
            yield Finding(again.location, self.code,
                          f"parameter '{again.name}' is declared again on node {again.node} "
                          "(ParameterAlreadyDeclaredException)",
                          ((again.first, f"'{again.name}' first declared here"),))

    def _use(self, use: ParameterUse, nodes: dict[str, NodeParameters]) -> Iterator[Finding]:
        if use.nodes is None or use.names is None:
            return
        if use.handled and use.how != "get_parameter_or":
            return  # ``try: get_parameter(...) except ParameterNotDeclaredException:`` handles it
        owners = [nodes.get(site) for site in use.nodes]
        if any(owner is None or owner.allows_undeclared for owner in owners):
            return
        # A declaration of a name the analysis does not know may be any name, but a read one
        # letter off a name the node declares is a misspelling of it (``auto_standup_on_stat``).
        near_miss_only = any(owner.open for owner in owners)
        for name in use.names:
            if name in BUILTIN_PARAMETERS or name.startswith(BUILTIN_PREFIXES):
                continue
            if any(name in owner.declared for owner in owners):
                continue
            node = owners[0]
            message = (f"parameter '{name}' is never declared on node {node.label}: "
                       f"{use.how}() {CONSEQUENCE.get(use.how, 'fails')}")
            declared = sorted({d for owner in owners for d in owner.declared})
            close = [d for d in declared if names.edit_distance(d, name, 2) <= 2]
            if near_miss_only and not _misspelt(name, close):
                continue
            if close:
                message += f"; did you mean '{close[0]}'?"
            yield Finding(use.location, self.code, message,
                          tuple((o.location, f"node {o.label} created here") for o in owners))
