"""The graph rules ROS001–ROS010, the rclpy-misuse rules ROS101–ROS107 and the launch and configuration rules ROS201–ROS206: one module per rule, run together over one extracted graph.

``RULES`` is the registry every front end (flake8 plugin, ``check`` command,
SARIF writer, the generated ``docs/rules.md``) reads, in code order.
"""
from __future__ import annotations

from typing import Iterable

from ..cpp.reporting import at_python_ends
from ..graph.model import Location, RosGraph
from .base import Finding, Rule, RuleConfig
from .ros001_publisher_without_subscriber import PublisherWithoutSubscriber
from .ros002_self_loop import SelfLoop
from .ros003_subscription_without_publisher import SubscriptionWithoutPublisher
from .ros004_message_type_mismatch import MessageTypeMismatch
from .ros005_qos_incompatible import QosIncompatible
from .ros006_invalid_name import InvalidName
from .ros007_duplicate_node_name import DuplicateNodeName
from .ros008_service_client_without_server import ServiceClientWithoutServer
from .ros009_action_client_without_server import ActionClientWithoutServer
from .ros010_unresolved_name import UnresolvedName
from .ros101_blocking_call_in_callback import BlockingCallInCallback
from .ros102_undeclared_parameter import UndeclaredParameter
from .ros103_callback_signature import CallbackSignature
from .ros104_publish_type_mismatch import PublishTypeMismatch
from .ros105_lifecycle_order import LifecycleOrder
from .ros106_invalid_timer_period import InvalidTimerPeriod
from .ros107_message_field import MessageField
from .ros201_unknown_executable import UnknownExecutable
from .ros202_ineffective_remap import IneffectiveRemap
from .ros203_invalid_launch_name import InvalidLaunchName
from .ros204_unknown_parameter import UnknownParameter
from .ros205_unmatched_parameter_section import UnmatchedParameterSection
from .ros206_security_policy import SecurityPolicy
from .shared import shared_indexes

RULES: tuple[Rule, ...] = (
    PublisherWithoutSubscriber(),
    SelfLoop(),
    SubscriptionWithoutPublisher(),
    MessageTypeMismatch(),
    QosIncompatible(),
    InvalidName(),
    DuplicateNodeName(),
    ServiceClientWithoutServer(),
    ActionClientWithoutServer(),
    UnresolvedName(),
    BlockingCallInCallback(),
    UndeclaredParameter(),
    CallbackSignature(),
    PublishTypeMismatch(),
    LifecycleOrder(),
    InvalidTimerPeriod(),
    MessageField(),
    UnknownExecutable(),
    IneffectiveRemap(),
    InvalidLaunchName(),
    UnknownParameter(),
    UnmatchedParameterSection(),
    SecurityPolicy(),
)

_BY_CODE: dict[str, Rule] = {rule.code: rule for rule in RULES}


def rule_by_code(code: str) -> Rule:
    """The rule with this code; ``KeyError`` for an unknown code."""
    return _BY_CODE[code]


def selected_rules(select: Iterable[str] | None = None) -> tuple[Rule, ...]:
    """The rules to run: the default-enabled ones, or those whose code starts with an entry of ``select``.

    Prefixes work as in flake8's ``--select`` (``ROS0`` selects ROS001–ROS010,
    including the off-by-default ROS010, because it is asked for explicitly).
    """
    if select is None:
        return tuple(rule for rule in RULES if rule.default_enabled)
    prefixes = tuple(select)
    return tuple(rule for rule in RULES if rule.code.startswith(prefixes))


def run_rules(graph: RosGraph, config: RuleConfig, select: Iterable[str] | None = None) -> list[Finding]:
    """Run the selected rules over ``graph``: findings sorted by location, code and message, duplicates dropped.

    Findings are located at Python ends only (:mod:`flake8_rosgraph.cpp.reporting`).
    """
    findings: set[Finding] = set()
    with shared_indexes():
        for rule in selected_rules(select):
            findings.update(rule.check(graph, config))
    return merge_same_text(at_python_ends(findings))  # C++ ends are partners only


def merge_same_text(findings: Iterable[Finding]) -> list[Finding]:
    """One finding per location, code and message, with the related locations of all of them.

    Two findings a user reads as one line are one problem told twice: a callback that two
    timers run reaches the same ``time.sleep()`` twice, a helper sleeps at two lines behind one
    call — each path has its own related locations, but the line printed is the same.
    A message that another one at the same place continues (``… has no server`` beside ``… has
    no server; did you mean '/ctrl_pkg/vehicle_state'?``: the end as written and as a launch file
    starts it, where only the latter's partner is near) is that finding told without its hint.
    """
    ordered = sorted(findings)
    messages: dict[tuple[Location, str], list[str]] = {}
    for finding in ordered:
        messages.setdefault((finding.location, finding.code), []).append(finding.message)
    related: dict[tuple, dict[tuple[Location, str], None]] = {}
    for finding in ordered:
        told = _told_in_full(finding.message, messages[(finding.location, finding.code)])
        related.setdefault((finding.location, finding.code, told), {}).update(dict.fromkeys(finding.related))
    return [Finding(location, code, message, tuple(others))
            for (location, code, message), others in sorted(related.items(), key=lambda kv: kv[0])]


def _told_in_full(message: str, at_place: list[str]) -> str:
    """The longest of the messages of one place and code that continues ``message``."""
    longer = [m for m in at_place if m.startswith(message + "; ")]
    return max(longer, key=lambda m: (len(m), m)) if longer else message


__all__ = ["RULES", "Finding", "Rule", "RuleConfig", "rule_by_code", "run_rules", "selected_rules"]
