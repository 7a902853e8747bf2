"""A stand-in for the graph extractor and the rules, small enough to trust by reading.

The plugin tests exercise the flake8 adapter, the cache and the outputs, not the
analysis: this module plays ``flake8_rosgraph.analysis.build_graph`` (a regex
over ``create_publisher(Type, 'topic'`` / ``create_subscription(Type, 'topic'``
calls, one node per file; ``$FAKE_ROSGRAPH_DELAY`` seconds slow) and ``flake8_rosgraph.rules.run_rules`` (ROS001 for a
topic nobody subscribes, ROS003 for one nobody publishes, ROS002 for a file that
subscribes to its own topic, ROS010 for a name that is not a literal). Real
``RULES`` metadata stays in place. A file containing ``FAKE_CRASH`` makes the
analysis raise. Each analysis appends ``<pid> <parent pid> <role> <root>`` to
``$FAKE_ROSGRAPH_LOG``, the role ``worker`` in a process of flake8's pool, else ``-``.

In-process tests call :func:`install`; subprocesses get it from the
``sitecustomize`` next to this file (put this directory on ``PYTHONPATH``), which
also reaches worker processes started by spawn or forkserver.
"""
from __future__ import annotations

import multiprocessing
import os
import re
import sys
import time
import types
from pathlib import Path

_CALL = re.compile(r"create_(publisher|subscription)\(\s*(\w+)\s*,\s*(?:['\"]([^'\"]+)['\"]|(\w+))")
_KIND = {"publisher": "publishers", "subscription": "subscriptions"}


def build_graph(root, stub_files=(), interface_dirs=(), buffers=(), *_cache_parts):
    """The fake analysis; what the cache passes to keep parts between runs is not used."""
    from flake8_rosgraph.graph.model import Entity, Location, RosGraph, RosNode

    root = Path(root)
    log = os.environ.get("FAKE_ROSGRAPH_LOG")
    if log:
        with open(log, "a", encoding="utf-8") as handle:
            role = "worker" if multiprocessing.parent_process() is not None else "-"
            handle.write(f"{os.getpid()} {os.getppid()} {role} {root}\n")
    time.sleep(float(os.environ.get("FAKE_ROSGRAPH_DELAY", "0")))
    graph = RosGraph()
    for path in sorted(root.rglob("*.py")):
        relative = path.relative_to(root)
        if any(part.startswith(".") for part in relative.parts):
            continue
        text = path.read_text(encoding="utf-8")
        if "FAKE_CRASH" in text:
            raise RuntimeError(f"fake analysis crashed on {relative.as_posix()}")
        node = RosNode(path.stem, "/", Location(relative.as_posix(), 1, 1))
        for number, line in enumerate(text.splitlines(), 1):
            for match in _CALL.finditer(line):
                kind, msg_type, literal, _variable = match.groups()
                name = None if literal is None else (literal if literal.startswith("/") else "/" + literal)
                location = Location(relative.as_posix(), number, match.start() + 1)
                node.entities.append(Entity(_KIND[kind], name, location, type=msg_type))
        if node.entities:
            graph.nodes.append(node)
    return graph


def run_rules(graph, config, select=None):
    from flake8_rosgraph.rules.base import Finding

    wanted = tuple(select) if select is not None else ("ROS001", "ROS002", "ROS003")
    external = {n if n.startswith("/") else "/" + n for n in config.external_names}
    pubs = [(n, e) for n, e in graph.entities("publishers")]
    subs = [(n, e) for n, e in graph.entities("subscriptions")]
    findings = []

    def emit(code, location, message, related=()):
        if code.startswith(wanted):
            findings.append(Finding(location, code, message, related))

    for kind, mine, peers, code, missing in (("published", pubs, subs, "ROS001", "subscriber"),
                                             ("subscribed", subs, pubs, "ROS003", "publisher")):
        peer_names = {e.name for _, e in peers}
        for _node, entity in mine:
            if entity.name is None:
                emit("ROS010", entity.location, "topic name cannot be determined statically")
            elif entity.name not in peer_names | {None} | external and None not in peer_names:
                emit(code, entity.location, f"topic '{entity.name}' has no {missing}")
    for node in graph.nodes:
        published = {e.name: e for e in node.of_kind("publishers") if e.name}
        for sub in node.of_kind("subscriptions"):
            if sub.name in published:
                pub = published[sub.name]
                emit("ROS002", sub.location,
                     f"node '{node.name}' subscribes to topic '{sub.name}' that it publishes "
                     f"(published at {pub.location.short()})", ((pub.location, f"publisher '{sub.name}'"),))
    return sorted(set(findings))


def install():
    """Make the fakes the analysis and rules that flake8_rosgraph uses in this process."""
    try:
        import flake8_rosgraph.rules as rules
    except ImportError:  # a process that has no flake8_rosgraph (pip in a fresh venv)
        return
    module = types.ModuleType("flake8_rosgraph.analysis")
    module.build_graph = build_graph
    sys.modules["flake8_rosgraph.analysis"] = module
    rules.run_rules = run_rules
