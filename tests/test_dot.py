"""The DOT writer: structure of the drawing, determinism and escaping.

The output is read back with a small parser for the subset of DOT that
:func:`to_dot` writes (one statement per line), so the tests assert on the
graph that Graphviz would see rather than on formatting details.
"""
from __future__ import annotations

import random
import re
import shutil
import subprocess
from dataclasses import dataclass, field, replace

import pytest

from flake8_rosgraph.graph.dot import to_dot
from flake8_rosgraph.graph.model import Entity, Location, RosGraph, RosNode
from flake8_rosgraph.rules.exempt import ExemptNames

QUOTED = r'"(?:[^"\\]|\\.)*"'
VERTEX_RE = re.compile(rf"^  ({QUOTED}) \[(.*)\];$")
EDGE_RE = re.compile(rf"^  ({QUOTED}) -> ({QUOTED})(?: \[(.*)\])?;$")
ATTR_RE = re.compile(rf"(\w+)=({QUOTED})")


def unquote(text: str) -> str:
    """Undo the writer's escaping; ``\\n`` in a label is a line break for Graphviz."""
    return re.sub(r"\\(.)", lambda m: "\n" if m.group(1) == "n" else m.group(1), text[1:-1])


def attrs_of(text: str | None) -> dict[str, str]:
    return {key: unquote(value) for key, value in ATTR_RE.findall(text or "")}


@dataclass
class Parsed:
    vertices: dict[str, dict[str, str]] = field(default_factory=dict)
    edges: dict[tuple[str, str], dict[str, str]] = field(default_factory=dict)
    legend: list[str] = field(default_factory=list)

    def vertex(self, label: str) -> tuple[str, dict[str, str]]:
        """The (id, attributes) of the only vertex whose first label line is ``label``."""
        found = [(key, a) for key, a in self.vertices.items() if a["label"].split("\n")[0] == label]
        assert len(found) == 1, (label, found)
        return found[0]

    def edge(self, source: str, target: str) -> dict[str, str]:
        return self.edges[(self.vertex(source)[0], self.vertex(target)[0])]


def parse(text: str) -> Parsed:
    lines = text.splitlines()
    start = lines.index("digraph rosgraph {")
    assert lines[-1] == "}" and text.endswith("}\n")
    assert all(line.startswith("//") for line in lines[:start])
    parsed = Parsed()
    body = lines[start + 1:-1]
    if "  subgraph cluster_legend {" in body:
        first = body.index("  subgraph cluster_legend {")
        last = body.index("  }", first)
        parsed.legend, body = body[first + 1:last], body[:first] + body[last + 1:]
    for line in body:
        if line.startswith(("  graph [", "  node [")):
            continue
        edge = EDGE_RE.match(line)
        if edge:
            key = (unquote(edge.group(1)), unquote(edge.group(2)))
            assert key not in parsed.edges, line
            parsed.edges[key] = attrs_of(edge.group(3))
            continue
        vertex = VERTEX_RE.match(line)
        assert vertex, f"unparsable line {line!r}"
        key = unquote(vertex.group(1))
        assert key not in parsed.vertices, line
        parsed.vertices[key] = attrs_of(vertex.group(2))
    for source, target in parsed.edges:
        assert source in parsed.vertices and target in parsed.vertices
    return parsed


def loc(line: int, path: str = "pkg/nodes.py") -> Location:
    return Location(path, line, 9)


def node(name: str | None, *entities: Entity, ns: str | None = "/", line: int = 1) -> RosNode:
    return RosNode(name, ns, loc(line), entities=list(entities))


def pub(topic: str | None, line: int = 1) -> Entity:
    return Entity("publishers", topic, loc(line), type="std_msgs/msg/String")


def sub(topic: str | None, line: int = 1) -> Entity:
    return Entity("subscriptions", topic, loc(line), type="std_msgs/msg/String")


def thesis_graph() -> RosGraph:
    """The four-node, eight-topic scenario of the thesis (figure 6.4)."""
    def topics(kind, *numbers):
        return [kind(f"/topic{n}", line=10 + n) for n in numbers]

    return RosGraph([
        node("node_1", *topics(pub, 7, 1), *topics(sub, 1, 3), line=1),
        node("node_2", *topics(pub, 1, 2, 3, 4, 5, 6, 7), *topics(sub, 7), line=2),
        node("node_3", *topics(sub, 2, 3, 6, 7, 4, 8), line=3),
        node("node_4", *topics(pub, 1, 3), *topics(sub, 2), line=4),
    ])


def test_thesis_scenario_vertices():
    parsed = parse(to_dot(thesis_graph()))
    for n in range(1, 5):
        _, attrs = parsed.vertex(f"/node_{n}")
        assert (attrs["shape"], attrs["fillcolor"], attrs["style"]) == ("ellipse", "aquamarine", "filled")
    fills = {n: parsed.vertex(f"/topic{n}")[1]["fillcolor"] for n in range(1, 9)}
    assert {n for n, fill in fills.items() if fill == "orange"} == {5, 8}
    assert {n for n, fill in fills.items() if fill == "yellow"} == {1, 2, 3, 4, 6, 7}
    assert all(parsed.vertex(f"/topic{n}")[1]["shape"] == "box" for n in range(1, 9))
    assert len(parsed.vertices) == 12


def test_thesis_scenario_edges_and_loops():
    parsed = parse(to_dot(thesis_graph()))
    labels = {key: attrs["label"] for key, attrs in parsed.vertices.items()}
    edges = {(labels[s], labels[t]): attrs for (s, t), attrs in parsed.edges.items()}
    assert len(edges) == 11 + 10  # publisher edges + subscription edges
    assert ("/node_2", "/topic5") in edges and ("/topic8", "/node_3") in edges
    assert ("/node_4", "/topic3") in edges and ("/topic2", "/node_4") in edges
    red = sorted(pair for pair, attrs in edges.items() if attrs.get("color") == "red")
    assert red == [
        ("/node_1", "/topic1"), ("/node_2", "/topic7"), ("/topic1", "/node_1"), ("/topic7", "/node_2"),
    ]
    # node_1 publishes topic7 and node_2 subscribes it: a normal edge, not a loop
    assert edges[("/node_1", "/topic7")] == {}


def test_output_is_independent_of_input_order():
    graph = thesis_graph()
    expected = to_dot(graph)
    rng = random.Random(4)
    for _ in range(5):
        nodes = [replace(n, entities=rng.sample(n.entities, len(n.entities))) for n in graph.nodes]
        rng.shuffle(nodes)
        assert to_dot(RosGraph(nodes)) == expected


def test_services_actions_and_clients():
    graph = RosGraph([
        node("server", Entity("services", "/add", loc(1)), Entity("action_servers", "/fib", loc(2))),
        node("caller", Entity("clients", "/add", loc(3)), Entity("action_clients", "/fib", loc(4))),
    ])
    parsed = parse(to_dot(graph))
    assert parsed.vertex("/add")[1]["shape"] == "component"
    assert parsed.vertex("/fib")[1]["shape"] == "box3d"
    # requests flow from the client through the service to the server
    assert parsed.edge("/add", "/server") == {}
    assert parsed.edge("/caller", "/add") == {"style": "dashed"}
    assert parsed.edge("/fib", "/server") == {}
    assert parsed.edge("/caller", "/fib") == {"style": "dashed"}


def test_same_name_as_topic_and_service_are_distinct_vertices():
    graph = RosGraph([node("n", pub("/x"), Entity("services", "/x", loc(2)))])
    parsed = parse(to_dot(graph))
    shapes = sorted(a["shape"] for a in parsed.vertices.values() if a["label"] == "/x")
    assert shapes == ["box", "component"]


def test_unknown_names_share_one_dashed_box_per_kind():
    graph = RosGraph([
        node("a", pub(None, 1), Entity("clients", None, loc(2))),
        node("b", sub(None, 3), pub(None, 4)),
    ])
    parsed = parse(to_dot(graph))
    unknown = {key: attrs for key, attrs in parsed.vertices.items() if attrs["label"] == "?"}
    assert sorted(attrs["shape"] for attrs in unknown.values()) == ["box", "component"]
    assert all(attrs["style"] == "dashed" and "fillcolor" not in attrs for attrs in unknown.values())
    topic_box = next(key for key, attrs in unknown.items() if attrs["shape"] == "box")
    touching = sorted((s, t) for s, t in parsed.edges if topic_box in (s, t))
    a, b = "node:/a@pkg/nodes.py", "node:/b@pkg/nodes.py"
    assert touching == [(a, topic_box), (b, topic_box), (topic_box, b)]
    # an unknown name is no evidence of a loop
    assert all("color" not in parsed.edges[pair] for pair in touching)


def test_nodes_with_unknown_names_stay_apart():
    graph = RosGraph([node(None, pub("/t"), line=5), node(None, sub("/t"), line=6), node("x", ns=None, line=7)])
    parsed = parse(to_dot(graph))
    unknown_nodes = [a for a in parsed.vertices.values() if a["shape"] == "ellipse"]
    assert sorted(a["label"] for a in unknown_nodes) == ["?", "?", "?/x"]
    assert all(a["style"] == "filled,dashed" for a in unknown_nodes)
    assert parsed.vertex("/t")[1]["fillcolor"] == "yellow"


def test_nodes_sharing_a_fqn_in_one_program_are_merged():
    graph = RosGraph([node("twin", pub("/t"), ns="/ns", line=1), node("twin", sub("/t"), ns="/ns", line=2)])
    parsed = parse(to_dot(graph))
    key, _ = parsed.vertex("/ns/twin")
    assert sorted(parsed.edges) == [(key, "topic:/t"), ("topic:/t", key)]
    assert all(attrs == {"color": "red"} for attrs in parsed.edges.values())


def test_nodes_sharing_a_fqn_in_different_programs_stay_apart():
    talker = RosNode("talker", "/", Location("demo_a/talker.py", 5, 9), entities=[pub("/chatter")])
    other = RosNode("talker", "/", Location("demo_b/talker.py", 7, 9), entities=[pub("/chatter")])
    parsed = parse(to_dot(RosGraph([talker, other])))
    talkers = sorted(key for key, attrs in parsed.vertices.items() if attrs["label"] == "/talker")
    assert talkers == ["node:/talker@demo_a/talker.py", "node:/talker@demo_b/talker.py"]
    assert sorted(parsed.edges) == [(key, "topic:/chatter") for key in talkers]


def test_infrastructure_names_are_subdued():
    graph = RosGraph([node("robot", pub("/tf"), pub("/odom"), Entity("clients", "/planner/get_parameters", loc(3)))])
    parsed = parse(to_dot(graph, exempt=ExemptNames.build()))
    for name in ("/tf", "/planner/get_parameters"):
        key, attrs = parsed.vertex(name)
        assert (attrs["fillcolor"], attrs["fontcolor"]) == ("gray92", "gray60")
        assert all(a.get("color") == "gray60" for pair, a in parsed.edges.items() if key in pair)
    assert parsed.vertex("/odom")[1]["fillcolor"] == "orange"  # a real orphan stays loud


def test_timers_and_parameters_in_the_node_label():
    graph = RosGraph([node(
        "talker",
        Entity("timers", None, loc(1), period=10.0),
        Entity("timers", None, loc(2), period=0.5),
        Entity("timers", None, loc(3)),
        Entity("parameters", "rate", loc(4), default=2),
        Entity("parameters", "frame", loc(5), default="map"),
        Entity("parameters", None, loc(6)),
        Entity("timers", None, loc(7), period=0.5),  # same line twice is shown once
    )])
    _, attrs = parse(to_dot(graph)).vertex("/talker")
    assert attrs["label"].split("\n") == [
        "/talker", "timer 0.5 s", "timer 10 s", "timer ? s", "param ?", "param frame = 'map'", "param rate = 2",
    ]


def test_odd_names_are_escaped():
    odd_node = 'say "hi"\\N'
    odd_topic = "/a\\l\nb\"c"
    graph = RosGraph([node(odd_node, pub(odd_topic), sub("/plain"))])
    text = to_dot(graph)
    parsed = parse(text)
    assert parsed.vertex("/" + odd_node)[0] == "node:/" + odd_node + "@pkg/nodes.py"
    key, attrs = parsed.vertex("/a\\l")
    assert key == "topic:" + odd_topic and attrs["label"] == odd_topic
    assert (f"node:/{odd_node}@pkg/nodes.py", f"topic:{odd_topic}") in parsed.edges
    # every statement stays on one line, and no raw Graphviz escape survives
    assert "\\N" not in text.replace("\\\\", "")
    assert len(text.splitlines()) == text.count("\n")


def test_empty_graph():
    text = to_dot(RosGraph())
    parsed = parse(text)
    assert parsed.vertices == {} and parsed.edges == {}
    labels = [attrs_of(line)["label"] for line in parsed.legend if "->" not in line]
    assert labels[:3] == ["Legend", "ROS node\n(timers, parameters)", "topic"]


@pytest.mark.slow
@pytest.mark.skipif(shutil.which("dot") is None, reason="Graphviz is not installed")
def test_graphviz_accepts_the_output():
    graph = thesis_graph()
    graph.nodes.append(node('odd "name"\\N', pub("/x\ny"), sub(None), line=9))
    result = subprocess.run(
        ["dot", "-Tplain"], input=to_dot(graph), capture_output=True, text=True, check=True, timeout=60,
    )
    drawn = [line for line in result.stdout.splitlines() if line.startswith("node ")]
    parsed = parse(to_dot(graph))
    assert len(parsed.vertices) == 4 + 8 + 1 + 2
    assert len(drawn) == len(parsed.vertices) + len([line for line in parsed.legend if "->" not in line]) - 1
