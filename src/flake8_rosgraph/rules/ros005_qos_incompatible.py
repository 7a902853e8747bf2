"""ROS005 qos-incompatible."""
from __future__ import annotations

from typing import Iterator

from ..graph.model import RosGraph
from .base import Finding, Rule, RuleConfig
from .qos_compat import qos_errors
from .topics import Endpoint, EndpointIndex
from .vocabulary import related
from .written import also_as_written

#: What a finding only the nodes as written in code show adds (see :mod:`.written`).
_AS_WRITTEN = " (when both run as written in code, `ros2 run`, without the launch files that start them apart)"


class QosIncompatible(Rule):
    """## What it does
    Checks every publisher / subscription pair of a topic for QoS policies the
    middleware refuses to match — exactly the *error* cases of rmw_dds_common's
    `qos_profile_check_compatible` (what rclpy's `qos_check_compatible` reports):

    - best-effort publisher, reliable subscription;
    - volatile publisher, transient-local subscription;
    - subscription with a deadline, publisher without one, or with a longer one;
    - automatic-liveliness publisher, manual-by-topic subscription;
    - subscription with a liveliness lease duration, publisher without one, or
      with a longer one.

    The QoS of each end is what rclpy would use: a plain depth (`10`) is
    `QoSProfile(depth=10)` (reliable, volatile, keep-last, no deadline);
    `QoSProfile(...)` fills what it is not given from the same defaults; the
    presets (`qos_profile_sensor_data`, `qos_profile_system_default`,
    `qos_profile_services_default`, `qos_profile_parameters`,
    `qos_profile_parameter_events`, `qos_profile_action_status_default`,
    `QoSPresetProfiles.SENSOR_DATA.value`,
    `QoSPresetProfiles.get_from_short_key('sensor_data')`) have rmw's values;
    deadlines and lease durations are read from `Duration(seconds=…,
    nanoseconds=…)`. Profiles built in variables, helper functions (in other
    modules too), class attributes and copies (`copy.copy(profile)`, then
    `profile.reliability = …`) are followed.

    ## Why is this bad?
    The two endpoints never connect. At run time ROS 2 only fires an
    "incompatible QoS" event (a log line, if anybody listens); the subscription
    just receives nothing. A classic case is subscribing reliably — with a plain
    depth — to a sensor driver that publishes with `qos_profile_sensor_data`
    (best effort).

    ## Known problems
    Only policies the analysis determined are compared: a profile or policy
    chosen by a parameter or a command-line option (an overridable default),
    one the analysis cannot follow, or that differs between the possible
    profiles of one call is unknown and never causes a finding. The
    middleware's *warnings* (a system-default or best-available policy on
    either side) are not findings either. A field changed on a profile held in
    an object attribute (`self.qos.reliability = …`) makes that policy unknown,
    since the attribute keeps both profiles. The finding is at the
    subscription, which requests more than the publisher offers; the publisher
    is the related location; a test fixture's publisher feeding the product
    it tests is reported at the fixture's end, with the product's subscription
    as related location (the test is what to fix). Ends that launch files start apart (a namespace,
    a remap) but that meet when both programs run as written (`ros2 run`) are
    compared too: the message says so.

    ## Example
    ```python
    self.create_publisher(LaserScan, 'scan', qos_profile_sensor_data)          # driver
    self.create_subscription(LaserScan, 'scan', self.on_scan,
                             QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE))
    ```

    ## Use instead
    ```python
    self.create_subscription(LaserScan, 'scan', self.on_scan, qos_profile_sensor_data)
    ```

    ## Options
    None.
    """

    code = "ROS005"
    name = "qos-incompatible"
    level = "error"
    precision = "high"  # SARIF/code-scanning precision: how often a finding is a real problem
    summary = "a publisher and a subscription of one topic have QoS that the middleware will refuse to match"

    def check(self, graph: RosGraph, config: RuleConfig) -> Iterator[Finding]:
        yield from also_as_written(self._pairs, graph, config, _AS_WRITTEN)

    def _pairs(self, graph: RosGraph, config: RuleConfig) -> Iterator[Finding]:
        index = EndpointIndex.build(graph)
        for sub in index.endpoints("subscriptions"):
            for pub in index.peers(sub):
                yield from self._mismatch(pub, sub, sub)
        # A test fixture's publisher feeds the product it tests, which does not see the fixture
        # (:mod:`.fixtures`): the pair is found from the fixture's side, and reported at its end.
        for pub in index.endpoints("publishers"):
            if pub.scope is not None:
                for sub in index.peers(pub):
                    if sub.scope is None:
                        yield from self._mismatch(pub, sub, pub)

    def _mismatch(self, pub: Endpoint, sub: Endpoint, at: Endpoint) -> Iterator[Finding]:
        """The finding of a pair whose QoS cannot match, at ``at`` (one of its ends)."""
        if not pub.entity.qos or not sub.entity.qos:
            return
        errors = qos_errors(pub.entity.qos, sub.entity.qos)
        if not errors:
            return
        role, other, other_role = (("subscription", pub, "publisher") if at is sub
                                   else ("publisher", sub, "subscription"))
        message = (f"QoS of {role} to '{at.entity.name}' cannot match the {other_role} at "
                   f"{other.entity.location.short()}: {'; '.join(errors)}")
        yield Finding(at.entity.location, self.code, message, (related(other.entity),))
