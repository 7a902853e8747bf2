"""Message facts: what the code builds, fills in and publishes, as plain data for ROS104/ROS107.

Read off the analysis by :mod:`.message_builder`. Abstract values become :class:`ValueShape`
tuples — the few things a message field's type check looks at — so the rules never see the
analyser's lattice. ``None`` stands for a value the analysis does not know: rules stay quiet
about it.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from .model import Location


@dataclass(frozen=True)
class ValueShape:
    """One possible value as a field check sees it.

    ``kind``: ``bool``, ``int``, ``float``, ``str``, ``bytes``, ``none`` (with ``value`` the
    constant), ``instance`` (of library class ``cls``; ``modelled`` when a stub models that
    class, so it is known not to be a message), ``sequence`` (``value`` is ``"list"`` or
    ``"tuple"``; ``length`` when known, ``items`` the shapes of elements it holds, ``None`` if
    unknown) or ``other``.
    """

    kind: str
    value: Any = None
    cls: str | None = None
    modelled: bool = False
    length: int | None = None
    items: tuple["ValueShape", ...] | None = None


@dataclass(frozen=True)
class FieldStore:
    """``path`` (``("header", "stamp")``) of an instance of ``message`` set to ``value``:
    an attribute store, or a constructor keyword (``keyword``)."""

    location: Location
    message: str
    path: tuple[str, ...]
    value: tuple[ValueShape, ...] | None
    keyword: bool


@dataclass(frozen=True)
class FieldRead:
    """``path`` of an instance of ``message`` read."""

    location: Location
    message: str
    path: tuple[str, ...]


@dataclass(frozen=True)
class Construction:
    """A call of library class ``message`` with ``positional`` positional arguments."""

    location: Location
    message: str
    positional: int


@dataclass(frozen=True)
class Publication:
    """``publisher.publish(msg)``: the message's shapes and the classes the publisher was
    created with (``None``: unknown)."""

    location: Location
    message: tuple[ValueShape, ...] | None
    publisher_types: tuple[str, ...] | None


@dataclass(frozen=True)
class ServiceReturn:
    """A service callback (defined at ``location``) of service class ``service`` returns ``value``."""

    location: Location
    callback: str
    service: str
    value: tuple[ValueShape, ...] | None


@dataclass
class MessageFacts:
    stores: list[FieldStore]
    reads: list[FieldRead]
    constructions: list[Construction]
    publications: list[Publication]
    service_returns: list[ServiceReturn]
