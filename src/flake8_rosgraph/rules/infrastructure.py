"""Slips of the pen for infrastructure topics, whose other end is never in the workspace.

``/joint_states``, ``/tf``, ``/clock`` … are exempt from the absence rules
(:mod:`.exempt`): their publishers and subscribers are robot_state_publisher,
ros2_control, simulators and rviz. So a subscription to ``/joint_state`` of
type ``sensor_msgs/msg/JointState`` finds no publisher and no near name in the
workspace either, and looks like one more interface to the outside — yet it is
the commonest typo there is. These topics have one well-known type each: an end
of exactly that type whose name is a slip (case, plural, one misspelt token:
:mod:`.near_miss`) of one of them meant it. A namespace more or less
(``/robot1/joint_states``) or another resolution of the written name is how
multi-robot systems use these topics, and is never taken for a slip.
"""
from __future__ import annotations

from .exempt import INFRASTRUCTURE_TYPES
from .near_miss import NearMissFinder, folded, is_family
from .topics import Endpoint

_TOPIC_KINDS = ("publishers", "subscriptions")


def infrastructure_slip(endpoint: Endpoint) -> str | None:
    """The infrastructure topic ``endpoint``'s name is a slip of, when its type is that topic's type."""
    entity = endpoint.entity
    if entity.kind not in _TOPIC_KINDS or entity.name is None or entity.type is None:
        return None
    tokens = [t for t in entity.name.split("/") if t]
    for topic, topic_type in sorted(INFRASTRUCTURE_TYPES.items()):
        if topic_type != entity.type or topic == entity.name or is_family(entity.name, topic):
            continue
        if folded(entity.name) & folded(topic) or NearMissFinder.spelling_distance(
                tokens, [t for t in topic.split("/") if t]) is not None:
            return topic
    return None
