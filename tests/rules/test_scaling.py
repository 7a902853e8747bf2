"""The wiring rules stay linear in the workspace size: no pass compares every name with every other."""
import time
import tracemalloc

from rosgraph_spec import findings, graph, node, pub, sub

import flake8_rosgraph.rules.near_miss as near_miss


def wide_graph(n):
    """n nodes in a ring, each with a dangling output and input of its own, all publishing one shared topic."""
    return graph(*[node(f"n{i}", pub(f"/ring{i}"), sub(f"/ring{(i + 1) % n}"), pub(f"/out_{i:05d}"),
                        sub(f"/in_{i:05d}x"), pub("/shared"), path=f"n{i}.py") for i in range(n)])


def test_near_miss_search_does_not_compare_all_pairs(monkeypatch):
    calls = []
    real = near_miss.transposition_distance
    monkeypatch.setattr(near_miss, "transposition_distance",
                        lambda a, b, limit: calls.append(1) or real(a, b, limit))
    n = 400
    result = findings(wide_graph(n), select=["ROS001", "ROS003"])
    assert len(result) == 2 * n   # every /out_ and /in_ is the odd one out of its node
    assert len(calls) < 10 * n    # all pairs would be n * n = 160000 comparisons


def long_name(i, width):
    """A long, deep, distinct name: a generated sensor path with a long leaf word."""
    leaf = "".join(chr(ord("a") + (i * 7 + k * 3) % 26) for k in range(width))
    return f"/fleet/site_{i % 13}/robot_{i % 17}/sensors/{leaf}_{i:05d}/data_stream_{leaf[::-1]}"


def thousand_long_names():
    n = 1000
    nodes = [node(f"n{i}", pub(long_name(i, 120)), sub(long_name(i, 120) + "x"), pub("/shared"), sub("/feed"),
                  path=f"pkg{i}/n.py") for i in range(n)]
    nodes.append(node("hub", sub("/shared"), pub("/feed"), path="hub.py"))
    return n, graph(*nodes)


def test_a_thousand_long_names_stay_fast(monkeypatch):
    calls = []
    real = near_miss.transposition_distance
    monkeypatch.setattr(near_miss, "transposition_distance",
                        lambda a, b, limit: calls.append(1) or real(a, b, limit))
    n, g = thousand_long_names()
    start = time.perf_counter()
    result = findings(g, select=["ROS001", "ROS003"])
    elapsed = time.perf_counter() - start
    # each node's own output and input differ by one trailing character, but a node's own end is never
    # its near miss: every long end is the odd one out of its node, with no candidate.
    assert len(result) == 2 * n
    assert len(calls) <= 4 * n     # each lookup verifies only the names sharing a key
    assert elapsed < 120, elapsed  # about 5 s idle; a pairwise or all-deletions index took minutes and gigabytes


def test_the_near_miss_index_of_a_thousand_long_names_is_small():
    _, g = thousand_long_names()
    ends = [ep for node_ in g.nodes for ep in node_.entities if ep.kind == "subscriptions"]
    tracemalloc.start()
    near_miss.NearMissFinder({ep.name: [] for ep in ends})
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    assert peak < 300 * 2**20, peak
