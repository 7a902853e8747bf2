"""Extraction mechanisms found on real repositories outside every test set, on realistic
multi-file packages: each follows what the code does at run time, and a near-identical twin
where following it must not invent a name or an entity."""
from __future__ import annotations

from pathlib import Path

from flake8_rosgraph.analysis import analyse, build_graph
from flake8_rosgraph.explain import explain

from test_workspace_discovery import PACKAGE_XML, write


def entities(root: Path, kinds: tuple[str, ...] = ("publishers", "subscriptions", "services")
             ) -> dict[str | None, list[tuple[str, str]]]:
    """Each node's entities of ``kinds`` as ``(kind, name or "?")``."""
    return {node.fqn: sorted((e.kind, e.name or "?") for e in node.entities if e.kind in kinds)
            for node in build_graph(root).nodes}


def explained(root: Path) -> list[tuple[str, int, str]]:
    graph, analysis = analyse(root)
    return [(e.site.path, e.site.line, e.status) for e in explain(analysis, graph).explanations]


# -- a dict only ever seen empty, filled through an alias ----------------------------------------
SWARM_SERVER = """
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import String
    from std_srvs.srv import Empty

    import radio_link


    class SwarmServer(Node):
        def __init__(self):
            super().__init__('swarm_server', automatically_declare_parameters_from_overrides=True)
            self.params = self.to_tree(self._parameters)
            self.names = {'all': 'all'}
            robots = self.params['robots']
            for robot in robots:
                if robots[robot]['enabled']:
                    self.names[robots[robot]['uri']] = robot
            self.link = radio_link.Swarm()
            self.link.connected.add_callback(self.on_connected)

        def to_tree(self, flat):
            '''{'robots.cf1.uri': …} -> {'robots': {'cf1': {'uri': …}}}'''
            tree = {}
            for key in flat:
                level = tree
                for part in key.split('.')[:-1]:
                    level = level.setdefault(part, {})
                level[key.split('.')[-1]] = flat[key].value
            return tree

        def on_connected(self, uri):
            for uri in self.names:
                if uri == 'all':
                    continue
                name = self.names[uri]
                self.create_publisher(String, name + '/status', 10)
                self.create_service(Empty, name + '/emergency', self.on_emergency)
            self.create_service(Empty, 'all/emergency', self.on_emergency)

        def on_emergency(self, request, response):
            return response


    def main():
        rclpy.init()
        rclpy.spin(SwarmServer())
"""


def test_a_dict_filled_through_an_alias_is_not_a_dead_end(tmp_path: Path) -> None:
    """``tree`` is filled only through ``level`` (an alias), so the analysis sees it empty;
    reading ``tree['robots'][robot]`` must be unknown, not a KeyError that makes the rest of
    ``__init__`` and every per-robot entity unreachable (crazyswarm2's server: 15 sites
    "never reached" before). The per-robot names come from parameters: unknown, with their
    suffix; no name is made up from the ``'all'`` entry the loop skips."""
    root = write(tmp_path, {
        "swarm/package.xml": PACKAGE_XML.format(name="swarm", build="ament_python"),
        "swarm/swarm/__init__.py": "",
        "swarm/swarm/server.py": SWARM_SERVER,
    })
    graph = build_graph(root)
    (node,) = graph.nodes
    got = sorted((e.kind, e.name or "?", e.name_text) for e in node.entities
                 if e.kind in ("publishers", "services"))
    assert got == [("publishers", "?", "name + '/status'"),
                   ("services", "/all/emergency", "'all/emergency'"),
                   ("services", "?", "name + '/emergency'")]
    assert not any(e.partial for e in node.entities)


def test_a_table_written_where_it_is_made_still_decides_its_lookups(tmp_path: Path) -> None:
    """The twin: a table the analysis sees filled where it is made (empty only before the loop
    that fills it) names exactly its entries: the empty first state adds no unknown."""
    root = write(tmp_path, {
        "fleet/package.xml": PACKAGE_XML.format(name="fleet", build="ament_python"),
        "fleet/fleet/__init__.py": "",
        "fleet/fleet/relay.py": """
            import rclpy
            from rclpy.node import Node
            from std_msgs.msg import String

            ROBOTS = {'scout': 'radio://0/80', 'hauler': 'radio://0/90'}


            class Relay(Node):
                def __init__(self):
                    super().__init__('relay')
                    links = {}
                    for name in ROBOTS:
                        links[name] = ROBOTS[name]
                    for name in links:
                        self.create_publisher(String, name + '/status', 10)


            def main():
                rclpy.init()
                rclpy.spin(Relay())
        """,
    })
    assert entities(root) == {"/relay": [("publishers", "/hauler/status"),
                                         ("publishers", "/scout/status")]}
