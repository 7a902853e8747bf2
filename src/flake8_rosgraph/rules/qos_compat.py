"""The QoS pairs the middleware refuses to match: rmw_dds_common ``qos_profile_check_compatible`` ERROR cases.

Mirrors ``rmw_dds_common/src/qos.cpp`` (the check rmw_fastrtps, rmw_cyclonedds
and rmw_connextdds share), error branches only — its *warnings* are about
"system default"/"unknown" policies, which static analysis cannot judge either.

Unlike the C code, a policy missing from the extracted QoS dict means "not
known statically" (or left at its default, which the extractor may not spell
out) and never takes part in a comparison: the rule must not guess.
Durations are seconds; ``0`` is rmw's "unspecified" default (``Duration()``
in rclpy), i.e. no deadline / no lease duration.
"""
from __future__ import annotations

from typing import Any, Mapping

#: The duration rmw treats as "not set" (``RMW_QOS_DEADLINE_DEFAULT``, ``..._LEASE_DURATION_DEFAULT``).
DURATION_DEFAULT = 0.0


def _seconds(value: Any) -> float | None:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return None
    return float(value)


def _duration_errors(policy: str, pub: Mapping[str, Any], sub: Mapping[str, Any]) -> list[str]:
    pub_s, sub_s = _seconds(pub.get(policy)), _seconds(sub.get(policy))
    if pub_s is None or sub_s is None or sub_s == DURATION_DEFAULT:
        return []
    label = policy.replace("_", " ")
    if pub_s == DURATION_DEFAULT:
        return [f"subscription has a {label} ({sub_s:g}s) but publisher has none"]
    if sub_s < pub_s:
        return [f"subscription {label} {sub_s:g}s is shorter than publisher's {pub_s:g}s"]
    return []


def qos_errors(pub: Mapping[str, Any], sub: Mapping[str, Any]) -> list[str]:
    """Why a publisher with QoS ``pub`` and a subscription with QoS ``sub`` cannot match (empty: no known reason)."""
    errors: list[str] = []
    if pub.get("reliability") == "best_effort" and sub.get("reliability") == "reliable":
        errors.append("best-effort publisher, reliable subscription")
    if pub.get("durability") == "volatile" and sub.get("durability") == "transient_local":
        errors.append("volatile publisher, transient-local subscription")
    errors += _duration_errors("deadline", pub, sub)
    if pub.get("liveliness") == "automatic" and sub.get("liveliness") == "manual_by_topic":
        errors.append("automatic-liveliness publisher, manual-by-topic subscription")
    errors += _duration_errors("liveliness_lease_duration", pub, sub)
    return errors
