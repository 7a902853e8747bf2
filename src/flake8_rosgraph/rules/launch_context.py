"""What the launch files of the workspace say about a node written in code, for the rules that
judge names by the namespace a node runs in.

A launch file whose executable the analysis cannot tie to code (a name built from a
launch argument, or an entry point it could not follow) may start any node of its
package: when it does so in a namespace, a node of that package is not known to run
at the root.
"""
from __future__ import annotations

from ..graph.model import RosGraph, RosNode

#: Launch targets not tied to code: the node they start may be any of the package's.
_UNMATCHED = ("unknown", "missing-executable")


def packages_maybe_namespaced(graph: RosGraph) -> frozenset[str]:
    """Packages a launch file starts an executable of, not tied to code, in a namespace."""
    return frozenset(
        launched.package for system in graph.systems for launched in system.nodes
        if launched.package and _unmatched(launched.target)
        and (launched.is_unresolved("namespace") or (launched.namespace or "/").strip("/")))


def _unmatched(target) -> bool:
    return target.status in _UNMATCHED or (target.status == "no-python" and target.entry is not None)


def in_package(node: RosNode, packages: frozenset[str]) -> bool:
    """Whether the node's code lies in a folder named like one of ``packages``."""
    return bool(packages) and not packages.isdisjoint(node.location.path.split("/")[:-1])


def launched_in_namespace(node: RosNode) -> bool:
    """Whether a launch file starts this node copy in a namespace other than the root."""
    return node.launch is not None and bool((node.namespace or "/").strip("/"))
