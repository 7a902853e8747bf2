"""The words findings use for each entity kind.

Kept in one place so that every rule says "topic", "service" or "action" and
"published at", "served at" the same way; users grep for these phrases.
"""
from __future__ import annotations

from ..graph.model import Entity, Location

#: What the name of an entity of this kind names.
NAME_NOUN: dict[str, str] = {
    "publishers": "topic", "subscriptions": "topic",
    "services": "service", "clients": "service",
    "action_servers": "action", "action_clients": "action",
    "timers": "timer", "parameters": "parameter",
}

#: One entity of this kind, as a developer calls it.
ENTITY_NOUN: dict[str, str] = {
    "publishers": "publisher", "subscriptions": "subscription",
    "services": "service server", "clients": "service client",
    "action_servers": "action server", "action_clients": "action client",
    "timers": "timer", "parameters": "parameter",
}

#: What an entity of this kind does to its name ("subscribed at nav/base.py:41").
VERB: dict[str, str] = {
    "publishers": "published", "subscriptions": "subscribed",
    "services": "served", "clients": "called",
    "action_servers": "served", "action_clients": "called",
}


def related(entity: Entity) -> tuple[Location, str]:
    """A related location for :attr:`Finding.related`: where, and what stands there."""
    name = f" '{entity.name}'" if entity.name is not None else ""
    return entity.location, f"{ENTITY_NOUN[entity.kind]}{name}"


def name_origin(entity: Entity) -> str | None:
    """Where a name a launch set through a parameter comes from, for a message (``parameter
    'topic' set at launch/robot.launch.py:12``); ``None`` for other names."""
    if not entity.name_parameters or entity.name_set_at is None:
        return None
    which = ", ".join(f"'{p}'" for p in entity.name_parameters)
    noun = "parameter" if len(entity.name_parameters) == 1 else "parameters"
    return f"{noun} {which} set at {entity.name_set_at.short()}"


def origin_related(entity: Entity) -> tuple[tuple[Location, str], ...]:
    """The setting that names ``entity``, as a related location (none for other names)."""
    if not entity.name_parameters or entity.name_set_at is None:
        return ()
    return ((entity.name_set_at, f"parameter '{entity.name_parameters[0]}' (name '{entity.name}')"),)
