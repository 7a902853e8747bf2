"""ROS004 message-type-mismatch."""
from __future__ import annotations

from collections import Counter
from typing import Iterator

from ..graph.model import PEER_KIND, RosGraph
from .base import Finding, Rule, RuleConfig
from .topics import Endpoint, EndpointIndex
from .vocabulary import NAME_NOUN, VERB, related

#: The kinds that produce a name's data (their type wins a tie): publishers, servers.
PRODUCERS: tuple[str, ...] = ("publishers", "services", "action_servers")


class MessageTypeMismatch(Rule):
    """## What it does
    Checks that all publishers and subscriptions of a topic use the same
    message type, and likewise servers and clients of a service or an action.

    ## Why is this bad?
    Endpoints with different types on one name never connect: DDS matches
    topics by name *and* type, so the subscription silently receives nothing
    (recent ROS 2 versions only log a warning at run time). It is an
    outright wiring error.

    ## Known problems
    Only endpoints whose types are known are compared, and never an end whose
    name rcl rejects (ROS006): it is never created. A node that creates the
    same endpoint with either type (a run-time choice such as `Twist` on one
    ROS distribution, `TwistStamped` on another, in one call or in two) is not
    reported when one of its choices agrees, and a call whose every choice
    disagrees is reported once, naming them all. Nor when every type in use on the name has both
    roles (publishers and subscriptions of that type): those are separate
    working systems, such as the same demo written in C++ and in Python. Test
    fixtures (nodes in `test/` folders and `test_*.py` modules) are compared only
    with the fixtures of their own tests (two test modules in a test folder
    never run together) and the production ends of the package
    they test, never with other packages; there the product's ends give the
    type the fixture's ends must have. The
    finding is reported
    at each endpoint whose type differs from the type most endpoints of the
    name use (on a tie, the publishers' or servers' type), since that is the
    side most likely wrong; the other side is the related location. When
    flake8 checks only some files (pre-commit, pull-request checks) and that
    endpoint's file is not among them, the finding is shown at the checked
    other side instead.

    ## Example
    ```python
    self.create_publisher(String, 'status', 10)                      # node A
    self.create_subscription(Int32, 'status', self.on_status, 10)    # node B
    ```

    ## Use instead
    ```python
    self.create_subscription(String, 'status', self.on_status, 10)   # node B
    ```

    ## Options
    None.
    """

    code = "ROS004"
    name = "message-type-mismatch"
    level = "error"
    precision = "high"  # SARIF/code-scanning precision: how often a finding is a real problem
    summary = "publishers / subscriptions of one topic disagree on the message type (same for services, actions)"

    def check(self, graph: RosGraph, config: RuleConfig) -> Iterator[Finding]:
        index = EndpointIndex.build(graph)
        for producer in PRODUCERS:
            consumer = PEER_KIND[producer]
            for name in sorted(set(index.names(producer)) | set(index.names(consumer))):
                # An end whose name rcl rejects (ROS006) never exists: it carries no type.
                typed = sorted((ep for ep in (*index.using(producer, name), *index.using(consumer, name))
                                if ep.entity.type is not None and ep.entity.invalid is None),
                               key=lambda ep: ep.sort_key)
                # Production ends are judged together; a test fixture's ends with what they see
                # (the fixtures of their scope, the production ends of the package under test),
                # reported at the fixture's own ends only (see :mod:`.fixtures`).
                yield from self._mismatches([ep for ep in typed if ep.scope is None], producer)
                # (two test modules never run together: each is judged on its own)
                for scope, run in sorted({(ep.scope, ep.run or "") for ep in typed if ep.scope is not None}):
                    own = [ep for ep in typed if ep.scope == scope and (ep.run or "") == run]
                    seen = [ep for ep in typed if own[0].sees(ep)]
                    # A test is judged against the product it tests: the product's ends give the type.
                    product = [ep for ep in seen if ep.scope is None]
                    yield from (f for f in self._mismatches(seen, producer, product or seen)
                                if any(f.location == ep.entity.location for ep in own))

    def _mismatches(self, typed: list[Endpoint], producer: str,
                    voters: list[Endpoint] | None = None) -> Iterator[Finding]:
        """The ends of ``typed`` whose type differs from the reference type, the one most
        ``voters`` (default: all of ``typed``) use."""
        counts = Counter(ep.entity.type for ep in typed)
        if len(counts) < 2:
            return
        voters = typed if voters is None else voters
        votes = Counter(ep.entity.type for ep in voters)
        producer_counts = Counter(ep.entity.type for ep in voters if ep.entity.kind == producer)
        reference = min(votes, key=lambda t: (-votes[t], -producer_counts[t], t))
        agreeing = [ep for ep in typed if ep.entity.type == reference]
        # A node that also has an endpoint of the same role with the reference type picks one at run time
        # (``Twist if distro == 'humble' else TwistStamped``): it can be configured to agree.
        configurable = {(id(ep.node), ep.entity.kind) for ep in agreeing}
        # A type whose publishers have subscribers of that type (servers, clients) is a working
        # system of its own: two of them on one name are alternative implementations (the same
        # demo in C++ and in Python), not a slip. Only ends whose type has no partner are reported.
        roles: dict[str, set[str]] = {}
        for ep in typed:
            roles.setdefault(ep.entity.type, set()).add(ep.entity.kind)
        complete = {t for t, kinds in roles.items() if len(kinds) == 2}
        # One call with several possible types (``Twist if stamped else TwistStamped``) is one
        # end with alternatives: reported once, with every type it may take.
        sites: dict[tuple, list[Endpoint]] = {}
        for ep in typed:
            entity = ep.entity
            if entity.type == reference or (id(ep.node), entity.kind) in configurable \
                    or (entity.type in complete and reference in complete):
                continue
            sites.setdefault((id(ep.node), entity.kind, entity.location, entity.name), []).append(ep)
        for alternatives in sites.values():
            entity = alternatives[0].entity
            types = " or ".join(f"'{t}'" for t in sorted({ep.entity.type for ep in alternatives}))
            # Name the other side when it exists: "subscribed as X but published as Y".
            witness = next((a for a in agreeing if a.entity.kind != entity.kind), agreeing[0]).entity
            message = (f"{NAME_NOUN[entity.kind]} '{entity.name}' {VERB[entity.kind]} as {types} "
                       f"but {VERB[witness.kind]} as '{reference}' at {witness.location.short()}")
            yield Finding(entity.location, self.code, message, tuple(related(a.entity) for a in agreeing))
