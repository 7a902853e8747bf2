"""Command line: ``flake8-rosgraph graph|check PATH`` (and ``python -m flake8_rosgraph``).

Exit status of ``graph``: 0 success, 2 usage or internal error;
of ``check``: 0 clean, 1 findings, 2 usage or internal error.  Diagnostics go to stderr, one per
line, and into the JSON output's ``diagnostics`` list.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
from pathlib import Path

from . import __version__, check_cli


def _graph(args: argparse.Namespace) -> int:
    from .analysis import analyse
    from .graph.dot import to_dot
    from .launch.api import apply, graph_to_json_obj, system_to_json

    root = Path(args.path)
    if not root.exists():
        print(f"flake8-rosgraph: error: no such file or directory: {args.path}", file=sys.stderr)
        return 2
    graph, analysis = analyse(root, [Path(s) for s in args.stubs])
    for diag in graph.diagnostics:
        if diag.severity == "info" and not args.verbose:
            continue  # kept in the JSON; stderr shows what may change the graph
        where = f"{diag.path}:{diag.line}: " if diag.path else ""
        print(f"{where}{diag.severity}: {diag.message}", file=sys.stderr)
    if args.explain:
        _explain(graph, analysis, args.verbose)
    shown = graph
    if args.launch:
        system = _find_system(graph, root, Path(args.launch))
        if system is None:
            print(f"flake8-rosgraph: error: {args.launch} is not a launch file of {args.path}",
                  file=sys.stderr)
            return 2
        shown = apply(graph, system)
        shown.diagnostics = sorted(set(graph.diagnostics) | set(system.problems))
        for problem in sorted(set(system.problems)):  # what the system may lack, said
            print(f"{problem.path}:{problem.line}: {problem.severity}: {problem.message}",
                  file=sys.stderr)
        unresolved = sum(1 for n in system.nodes if n.unresolved)
        if not system.complete:
            print(f"flake8-rosgraph: {args.launch} is not fully followed: "
                  f"{len(set(system.problems))} construct(s) not followed, "
                  f"{unresolved} node(s) with unknown values", file=sys.stderr)
    if args.format == "dot":
        text = to_dot(shown)
    else:
        obj = graph_to_json_obj(shown)
        if not args.launch:
            obj["systems"] = [system_to_json(s) for s in graph.systems]
        text = json.dumps(obj, indent=1, ensure_ascii=False) + "\n"
    if args.output:
        Path(args.output).write_text(text, encoding="utf-8")
    else:
        sys.stdout.write(text)
    return 0


def _explain(graph, analysis, verbose: bool) -> None:
    """Creation sites missing from the graph or known only partly, one line each (stderr)."""
    from .explain import explain
    if analysis is None:
        print("flake8-rosgraph: --explain: the analysis did not complete; nothing to explain",
              file=sys.stderr)
        return
    report = explain(analysis, graph)
    for item in report.gaps():
        print(item.line(), file=sys.stderr)
    if verbose:
        print(report.summary(), file=sys.stderr)


def _find_system(graph, root: Path, launch_file: Path):
    """The system of ``launch_file`` among those found under ``root``."""
    base = root.resolve() if root.is_dir() else root.resolve().parent
    try:
        wanted = launch_file.resolve().relative_to(base).as_posix()
    except ValueError:
        return None
    return next((s for s in graph.systems if s.launch_file == wanted), None)


def make_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="flake8-rosgraph",
                                     description="Static ROS 2 computation graph of rclpy code.")
    parser.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    sub = parser.add_subparsers(dest="command", required=True)
    graph = sub.add_parser("graph", help="print the ROS computation graph of PATH")
    graph.add_argument("path", help="workspace folder (or a single file)")
    graph.add_argument("--format", choices=("json", "dot"), default="json")
    graph.add_argument("--output", "-o", help="write to this file instead of stdout")
    graph.add_argument("--stubs", action="append", default=[], metavar="FILE",
                       help="extra library model (TOML); repeatable")
    graph.add_argument("--verbose", "-v", action="store_true",
                       help="also print informational diagnostics (analysis precision bounds)")
    graph.add_argument("--explain", action="store_true",
                       help="list on stderr every creation call (node, publisher, subscription, "
                            "service, client, timer, action) missing from the graph or known only "
                            "partly, with the reasons; with --verbose, a one-line count")
    graph.add_argument("--launch", metavar="FILE",
                       help="print the system this launch file starts (names, namespaces and "
                            "remappings applied) instead of the code-level graph")
    graph.set_defaults(run=_graph)
    check_cli.add_parser(sub)
    return parser


def main(argv: list[str] | None = None) -> int:
    parser = make_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:
        return int(exc.code or 0) and 2
    try:
        return args.run(args)
    except BrokenPipeError:  # the reader went away (``| head``): not an error of ours
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    except Exception as exc:  # one clear line, never a traceback
        print(f"flake8-rosgraph: internal error: {type(exc).__name__}: {exc}", file=sys.stderr)
        return 2
