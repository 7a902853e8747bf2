"""Which ends of one creation site the separate calls of a shared helper name.

A helper that creates the entity its caller names (``def _client(self, srv, name): return
self.create_client(srv, name)``) runs its creation call once per calling context, and the
analysis records one effect per context. The names of one effect are alternatives of one end
(``'a' if sim else 'b'``: one client, two configurations); the names of separate effects are
separate ends (``self._client(Trigger, '/start')`` and ``self._client(Trigger, '/stop')``: two
clients), as they would be written at two creation calls.
"""
from __future__ import annotations

from dataclasses import dataclass, field, replace

from .model import Entity, Location, RosNode


@dataclass
class SiteCalls:
    """The name sets each call of a creation site gave, per node and site."""

    _calls: dict[tuple[int, Location, str], set[frozenset[str | None]]] = field(default_factory=dict)

    def add(self, node: RosNode, made: list[Entity]) -> None:
        """Record the entities one effect made on ``node`` (all at one site)."""
        if not made:
            return
        names = frozenset(None if e.partial else e.name for e in made)
        self._calls.setdefault((id(node), made[0].location, made[0].kind), set()).add(names)

    def marked(self, node: RosNode, entity: Entity) -> Entity:
        """``entity``, marked :attr:`~.model.Entity.own_call` when its site ran in calls that
        named different ends and one of them named this end alone."""
        calls = self._calls.get((id(node), entity.location, entity.kind), set())
        if entity.name is None or entity.partial or len(calls) < 2 or frozenset({entity.name}) not in calls:
            return entity
        return replace(entity, own_call=True)
