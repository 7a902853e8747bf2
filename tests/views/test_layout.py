"""The layered layout: columns follow the data, cycles and long edges are handled, the result is stable."""
from __future__ import annotations

import random

from flake8_rosgraph.graph.layout import LAYER_GAP, layered_layout

SIZE = (80.0, 20.0)


def sizes(*names: str) -> dict[str, tuple[float, float]]:
    return {name: SIZE for name in names}


def column(layout, name: str) -> int:
    return round(layout.boxes[name].x / LAYER_GAP)


def test_columns_follow_the_data_flow():
    edges = [("camera", "/image"), ("/image", "detector"), ("detector", "/objects"), ("/objects", "planner")]
    layout = layered_layout(edges, sizes("camera", "/image", "detector", "/objects", "planner"))
    assert [column(layout, n) for n in ("camera", "/image", "detector", "/objects", "planner")] == [0, 1, 2, 3, 4]


def test_a_feedback_loop_still_gets_columns():
    edges = [("controller", "/cmd"), ("/cmd", "base"), ("base", "/odom"), ("/odom", "controller")]
    layout = layered_layout(edges, sizes("controller", "/cmd", "base", "/odom"))
    assert sorted(column(layout, n) for n in ("controller", "/cmd", "base", "/odom")) == [0, 1, 2, 3]
    back = next(edge for edge in edges if column(layout, edge[0]) > column(layout, edge[1]))
    # the edge closing the loop runs right to left, through a waypoint in every column between
    waypoints = layout.routes[back]
    assert len(waypoints) == column(layout, back[0]) - column(layout, back[1]) - 1 > 0
    assert [x for x, _ in waypoints] == sorted((x for x, _ in waypoints), reverse=True)


def test_an_input_nobody_publishes_sits_next_to_its_reader():
    edges = [("a", "/t1"), ("/t1", "b"), ("b", "/t2"), ("/t2", "c"), ("/typo", "c")]
    layout = layered_layout(edges, sizes("a", "/t1", "b", "/t2", "c", "/typo"))
    assert column(layout, "/typo") == column(layout, "c") - 1


def test_long_edges_get_one_waypoint_per_column_crossed():
    edges = [("a", "/t1"), ("/t1", "b"), ("b", "/t2"), ("/t2", "c"), ("a", "/t3"), ("/t3", "c")]
    layout = layered_layout(edges, sizes("a", "/t1", "b", "/t2", "c", "/t3"))
    crossed = column(layout, "c") - column(layout, "/t3") - 1 + column(layout, "/t3") - column(layout, "a") - 1
    assert len(layout.routes[("a", "/t3")]) + len(layout.routes[("/t3", "c")]) == crossed


def test_no_overlap_and_independent_of_input_order():
    rng = random.Random(3)
    names = [f"n{i}" for i in range(40)]
    edges = [(rng.choice(names), rng.choice(names)) for _ in range(80)]
    first = layered_layout(edges, sizes(*names))
    boxes = list(first.boxes.values())
    for i, a in enumerate(boxes):
        for b in boxes[i + 1:]:
            assert abs(a.x - b.x) >= SIZE[0] or abs(a.y - b.y) >= SIZE[1]
    shuffled = edges[:]
    rng.shuffle(shuffled)
    again = layered_layout(shuffled, dict(reversed(list(sizes(*names).items()))))
    assert again == first
