"""The wiring rules stay linear in the workspace size: no pass compares every name with every other."""
from rosgraph_spec import findings, graph, node, pub, sub

import flake8_rosgraph.rules.near_miss as near_miss


def wide_graph(n):
    """n nodes in a ring, each with a dangling output and input of its own, all publishing one shared topic."""
    return graph(*[node(f"n{i}", pub(f"/ring{i}"), sub(f"/ring{(i + 1) % n}"), pub(f"/out_{i:05d}"),
                        sub(f"/in_{i:05d}x"), pub("/shared"), path=f"n{i}.py") for i in range(n)])


def test_near_miss_search_does_not_compare_all_pairs(monkeypatch):
    calls = []
    real = near_miss.edit_distance
    monkeypatch.setattr(near_miss, "edit_distance", lambda a, b, limit: calls.append(1) or real(a, b, limit))
    n = 400
    result = findings(wide_graph(n), select=["ROS001", "ROS003"])
    assert len(result) == 2 * n   # every /out_ and /in_ is the odd one out of its node
    assert len(calls) < 10 * n    # all pairs would be n * n = 160000 comparisons
