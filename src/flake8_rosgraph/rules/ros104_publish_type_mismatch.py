"""ROS104 publish-type-mismatch."""
from __future__ import annotations

from typing import Iterator

from ..graph.messages import Publication
from ..graph.model import Location, RosGraph
from ..interfaces.catalogue import display_name, message_key
from ..interfaces.field_values import describe, without_none_alternative
from .base import Finding, Rule, RuleConfig

_WRONG_KINDS = frozenset({"bool", "int", "float", "str", "bytes", "none", "sequence"})


def wrong_values(shapes, expected: set[str]) -> list[str]:
    """Descriptions of the possible values that are not a message of one of the ``expected`` keys
    (``None`` beside other possibilities is an error path the caller handles, not judged)."""
    out = []
    shapes = list(shapes)
    for shape in without_none_alternative(shapes):
        if shape.kind == "instance":
            key = message_key(shape.cls)
            if (key is not None and key not in expected) or (key is None and shape.modelled):
                out.append(describe(shape))
        elif shape.kind in _WRONG_KINDS:
            out.append(describe(shape))
    return out


class PublishTypeMismatch(Rule):
    """## What it does
    Checks that `publish(msg)` is given a message of the type the publisher was
    created with, and that a service callback returns its own service's
    `Response`.

    ## Why is this bad?
    rclpy checks the type at run time: `publish` raises
    `TypeError: Expected <type>, got <type>` (and a service with a wrong
    response fails when it sends it). The node dies the first time that code
    runs, typically in a timer or callback long after start-up, and often only
    on the branch nobody tested. Publishers created in a base class in one
    module and used in another make this easy to get wrong.

    ## Known problems
    Only messages whose class the analysis knows are judged; a message whose
    value is unknown (returned by an unmodelled library, or depending on a
    run-time choice it cannot follow) is not reported. A publisher created with
    one of several types (`Twist if stamped else TwistStamped`) accepts any of
    them.

    ## Example
    ```python
    self.pub = self.create_publisher(Int32, 'count', 10)   # base.py
    ...
    msg = String()
    msg.data = 'hello'
    self.pub.publish(msg)                                   # talker.py
    ```

    ## Use instead
    ```python
    msg = Int32()
    msg.data = 42
    self.pub.publish(msg)
    ```

    ## Options
    None.
    """

    code = "ROS104"
    name = "publish-type-mismatch"
    level = "error"
    precision = "high"  # SARIF/code-scanning precision: how often a finding is a real problem
    summary = "publish(msg) with a message whose type differs from the publisher's type; a service callback returning another type's response"

    def check(self, graph: RosGraph, config: RuleConfig) -> Iterator[Finding]:
        facts = graph.messages
        if facts is None:
            return
        # One call site may publish on several publishers (``self.pub`` set on two branches,
        # each with its own message type): judged together, what may be published there
        # against every type those publishers take.
        by_site: dict[Location, list[Publication]] = {}
        for pub in facts.publications:
            by_site.setdefault(pub.location, []).append(pub)
        for location, pubs in sorted(by_site.items()):
            if any(p.publisher_types is None or p.message is None for p in pubs):
                continue  # unknown in one calling context: unknown (see ROS107's merge_contexts)
            expected = {message_key(cls) for p in pubs for cls in p.publisher_types}
            if None in expected:
                continue
            shapes = sorted({s for p in pubs for s in p.message}, key=repr)
            wrong = wrong_values(shapes, expected)
            if wrong:
                types = " or ".join(sorted(display_name(k) for k in expected))
                yield Finding(location, self.code,
                              f"publishes {' or '.join(sorted(set(wrong)))} on a publisher of {types}")
        for ret in facts.service_returns:
            response = message_key(ret.service + ".Response")
            if ret.value is None or response is None:
                continue
            for wrong in wrong_values((s for s in ret.value if s.kind == "instance"), {response}):
                yield Finding(ret.location, self.code,
                              f"service callback {ret.callback} returns {wrong}, not a "
                              f"{display_name(response)}")
