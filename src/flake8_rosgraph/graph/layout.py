"""A layered left-to-right layout of a picture, by data flow.

Readers of a ROS graph follow data from sensors to actuators, so vertices are
placed in columns (layers) along the flow of data and, within a column, in an
order that keeps edges short and crossings few — the classic Sugiyama scheme,
small enough to own:

1. cycles (feedback loops are common in robots) are broken by reversing the
   back edges of a depth-first search taken in id order;
2. each vertex's layer is the longest path to it from a source
   (``networkx`` does the graph work), and a source then moves right to sit
   just before its nearest successor (a topic nobody publishes sits next to
   its subscriber, not in the first column);
3. an edge spanning several layers gets a waypoint in each layer it crosses,
   so it is routed around the vertices there instead of through them;
4. vertices and waypoints in each layer are ordered by the barycentre of
   their neighbours in the previous (then the next) layer, a few sweeps each
   way;
5. coordinates: fixed column spacing, rows stacked by each vertex's height,
   and every layer centred vertically.

Isolated vertices go to the first column. Everything is ordered by vertex id
before any choice, so the layout is deterministic.
"""
from __future__ import annotations

from dataclasses import dataclass

import networkx as nx

#: Horizontal distance between layers, and vertical gap between vertices, in drawing units.
LAYER_GAP = 260.0
ROW_GAP = 18.0
#: Barycentre sweeps (each goes down then up).
SWEEPS = 4
#: The height a waypoint takes in its layer.
WAYPOINT_HEIGHT = 6.0


@dataclass(frozen=True)
class Box:
    """A vertex's place: centre and size."""

    x: float
    y: float
    width: float
    height: float


def _acyclic(graph: nx.DiGraph) -> nx.DiGraph:
    """``graph`` with the back edges of an id-ordered depth-first search reversed."""
    dag = nx.DiGraph()
    dag.add_nodes_from(sorted(graph.nodes))
    state: dict[str, int] = {}  # 1 on the stack, 2 done
    for start in sorted(graph.nodes):
        if start in state:
            continue
        state[start] = 1
        stack = [(start, iter(sorted(graph.successors(start))))]
        while stack:
            vertex, children = stack[-1]
            child = next(children, None)
            if child is None:
                state[vertex] = 2
                stack.pop()
            elif state.get(child) == 1:
                dag.add_edge(child, vertex)  # a back edge: reverse it
            else:
                dag.add_edge(vertex, child)
                if child not in state:
                    state[child] = 1
                    stack.append((child, iter(sorted(graph.successors(child)))))
    return dag


@dataclass(frozen=True)
class Layout:
    """Where each vertex goes, and the waypoints of each edge ``(source, target)`` from source to target."""

    boxes: dict[str, Box]
    routes: dict[tuple[str, str], list[tuple[float, float]]]


def _layers(dag: nx.DiGraph) -> dict[str, int]:
    layer: dict[str, int] = {}
    for vertex in nx.lexicographical_topological_sort(dag):
        layer[vertex] = max((layer[p] + 1 for p in dag.predecessors(vertex)), default=0)
    for vertex in sorted(dag.nodes):
        if dag.in_degree(vertex) == 0 and dag.out_degree(vertex) > 0:
            layer[vertex] = min(layer[s] for s in dag.successors(vertex)) - 1
    return layer


def _with_waypoints(dag: nx.DiGraph, layer: dict[str, int]) -> tuple[nx.DiGraph, dict[tuple[str, str], list[str]]]:
    """``dag`` with every long edge split at one waypoint per layer crossed; the waypoints of each edge."""
    split = nx.DiGraph()
    split.add_nodes_from(dag.nodes)
    chains: dict[tuple[str, str], list[str]] = {}
    for source, target in sorted(dag.edges):
        chain = [f"\0{source}\0{target}\0{k}" for k in range(layer[source] + 1, layer[target])]
        for waypoint, k in zip(chain, range(layer[source] + 1, layer[target])):
            layer[waypoint] = k
        path = [source, *chain, target]
        split.add_edges_from(zip(path, path[1:]))
        chains[(source, target)] = chain
    return split, chains


def _order(dag: nx.DiGraph, layer: dict[str, int]) -> list[list[str]]:
    columns: list[list[str]] = [[] for _ in range(max(layer.values(), default=-1) + 1)]
    for vertex in sorted(layer):
        columns[layer[vertex]].append(vertex)
    for _ in range(SWEEPS):
        for index in range(1, len(columns)):
            _sort_by_barycentre(columns[index], columns[index - 1], dag.predecessors)
        for index in range(len(columns) - 2, -1, -1):
            _sort_by_barycentre(columns[index], columns[index + 1], dag.successors)
    return columns


def _sort_by_barycentre(column: list[str], fixed: list[str], neighbours) -> None:
    position = {vertex: i for i, vertex in enumerate(fixed)}

    def key(item: tuple[int, str]) -> tuple[float, int]:
        index, vertex = item
        seen = [position[n] for n in neighbours(vertex) if n in position]
        return (sum(seen) / len(seen) if seen else float(index), index)

    column[:] = [vertex for _, vertex in sorted(enumerate(column), key=key)]


def layered_layout(edges: list[tuple[str, str]], sizes: dict[str, tuple[float, float]]) -> Layout:
    """A box per vertex of ``sizes`` (width, height), columns left to right along ``edges``."""
    graph = nx.DiGraph()
    graph.add_nodes_from(sizes)
    graph.add_edges_from((s, t) for s, t in edges if s != t and s in sizes and t in sizes)
    dag = _acyclic(graph)
    layer = _layers(dag)
    split, chains = _with_waypoints(dag, layer)
    columns = _order(split, layer)
    height = {v: sizes[v][1] if v in sizes else WAYPOINT_HEIGHT for column in columns for v in column}
    heights = [sum(height[v] for v in column) + ROW_GAP * max(len(column) - 1, 0) for column in columns]
    tallest = max(heights, default=0.0)
    centres: dict[str, tuple[float, float]] = {}
    for index, column in enumerate(columns):
        y = (tallest - heights[index]) / 2
        for vertex in column:
            centres[vertex] = (index * LAYER_GAP, y + height[vertex] / 2)
            y += height[vertex] + ROW_GAP
    boxes = {v: Box(*centres[v], *sizes[v]) for v in sizes}
    routes: dict[tuple[str, str], list[tuple[float, float]]] = {}
    for (source, target), chain in chains.items():
        points = [centres[w] for w in chain]
        if graph.has_edge(source, target):
            routes[(source, target)] = points
        if graph.has_edge(target, source):  # a back edge, drawn from its real source
            routes[(target, source)] = points[::-1]
    return Layout(boxes, routes)
