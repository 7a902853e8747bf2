"""Entry points of launch analysis for the CLI, the plugin and the rules:

* :func:`systems_for` — every launch file of the workspace executed
  statically (Python, XML and YAML front ends), each node bound to the code
  its executable runs;
* :func:`apply` — one system's instantiated graph (nodes renamed,
  namespaced and remapped per rcl, each carrying ``launch`` info);
* :func:`judged_graph` — the graph the ROS0xx rules should judge: launched
  instances from every system plus the code nodes no launch file starts;
* :func:`system_to_json` / :func:`graph_to_json_obj` — the JSON forms.
"""
from __future__ import annotations

from pathlib import Path
from typing import Any, Callable, Mapping

from ..graph.json_out import to_json_obj
from ..graph.model import Diagnostic, RosGraph
from .discover import LaunchReader, PythonLaunches, frontend_launch_files
from .execute import Executor
from .instantiate import Instantiator, apply_systems
from .model import ExecutableRef, LaunchedNode, System
from .packages import PackageIndex, find_packages
from .targets import TargetIndex


def systems_for(root: Path, graph: RosGraph, python: PythonLaunches | None,
                targets: Mapping[str, ExecutableRef] | None,
                diagnostics: list[Diagnostic] | None = None, walk: bool = True,
                packages: PackageIndex | None = None, frontend: list[str] | None = None) -> list[System]:
    """Every launch system under ``root``, one per launch file, in path order.

    ``python``: what the analysis read of each Python launch file, ``targets``: where each
    Python executable leads (both ``None`` when the Python code was not analysed);
    ``packages``, ``frontend``: the workspace's packages and XML/YAML launch files, when
    already found.  Each system is executed and instantiated on its own: a failure in one is a
    problem of that system, never the loss of the others.  Files, folders and packages that
    cannot be read are added to ``diagnostics``.  Without ``walk`` (a single file analysed)
    only the analysed Python launch files count: no folder around them is searched for
    packages or launch files.
    """
    root = Path(root)
    diagnostics = [] if diagnostics is None else diagnostics
    if packages is None:
        packages = find_packages(root) if walk else PackageIndex()
        diagnostics.extend(packages.diagnostics)
    executor = Executor(root, packages, LaunchReader(root, python), TargetIndex(targets, packages).resolve)
    if frontend is None:
        frontend = frontend_launch_files(root, diagnostics) if walk else []
    files = sorted(set(python or ()) | set(frontend))
    binder = Instantiator(root)
    systems = [_bound(binder, graph, _isolated(lambda: executor.system(path), path)) for path in files]
    for system in systems:
        system.problems = sorted(set(system.problems))
    return systems


def _failed(path: str, exc: Exception) -> System:
    """A system that could not be read: no nodes, one problem naming the failure."""
    system = System(path, files=[path], blind=True)
    system.problems.append(Diagnostic(path, 1, f"launch file not analysed: internal error: "
                                               f"{type(exc).__name__}: {exc}"[:300]))
    return system


def _isolated(build: Callable[[], System], path: str) -> System:
    try:
        return build()
    except Exception as exc:  # one launch file's failure costs that system only
        return _failed(path, exc)


def _bound(binder: Instantiator, graph: RosGraph, system: System) -> System:
    """``system`` with its instances bound to the code graph, or a failed system if that raises."""
    try:
        binder.system(graph, system)
        return system
    except Exception as exc:
        failed = _failed(system.launch_file, exc)
        binder.system(graph, failed)
        return failed


def system_for_file(root: Path, graph: RosGraph, python: PythonLaunches | None,
                    targets: Mapping[str, ExecutableRef] | None, launch_file: Path) -> System:
    """The system of one launch file (``graph --launch FILE``)."""
    root = Path(root)
    path = Path(launch_file).resolve().relative_to(root.resolve()).as_posix()
    packages = find_packages(root)
    executor = Executor(root, packages, LaunchReader(root, python), TargetIndex(targets, packages).resolve)
    system = _bound(Instantiator(root), graph, _isolated(lambda: executor.system(path), path))
    system.problems = sorted(set(system.problems))
    return system


def apply(graph: RosGraph, system: System) -> RosGraph:
    """The instantiated graph of ``system`` (launched nodes; other code nodes as written)."""
    return apply_systems(graph, [system], placeholders=True)


def judged_graph(graph: RosGraph, systems: list[System]) -> RosGraph:
    """What the graph rules judge: a topic connected after remapping is connected."""
    judged = apply_systems(graph, systems, placeholders=False)
    judged.diagnostics = list(graph.diagnostics)
    judged.systems = systems
    judged.messages, judged.interfaces = graph.messages, graph.interfaces
    judged.usage, judged.policies = graph.usage, graph.policies
    return judged


def _launched_json(node: LaunchedNode) -> dict[str, Any]:
    out: dict[str, Any] = {
        "package": node.package, "executable": node.executable,
        "name": node.name, "namespace": node.namespace,
        "file": node.launch_file, "line": node.location.line, "column": node.location.column,
        "status": node.target.status, "entry": node.target.entry,
        "remappings": [{"from": r.source, "to": r.target, "line": r.location.line}
                       for r in node.remaps],
        "parameters": [{"name": p.name, "value": p.value} for p in node.params],
        "parameter_files": [f.path if f.path is not None else f.written for f in node.param_files],
    }
    if node.conditional:
        out["conditional"] = True
    if node.unresolved:
        out["unresolved"] = list(node.unresolved)
    return out


def system_to_json(system: System) -> dict[str, Any]:
    """One system for the ``"systems"`` list of the graph JSON."""
    return {
        "launch_file": system.launch_file,
        "files": list(system.files),
        "complete": system.complete,
        "arguments": dict(sorted(system.arguments.items())),
        "nodes": [_launched_json(n) for n in system.nodes],
        "problems": [{"path": d.path, "line": d.line, "message": d.message} for d in system.problems],
    }


def graph_to_json_obj(graph: RosGraph) -> dict[str, Any]:
    """``to_json_obj`` plus ``"launch"`` on launched nodes (contract rosgraph/1 allows extra keys)."""
    out = to_json_obj(graph)
    for node, entry in zip(graph.nodes, out["nodes"]):
        if node.launch is not None:
            entry["launch"] = node.launch
    return out


__all__ = ["System", "apply", "graph_to_json_obj", "judged_graph", "system_for_file",
           "system_to_json", "systems_for"]
