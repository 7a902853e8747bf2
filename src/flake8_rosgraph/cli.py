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
import traceback
from pathlib import Path

from . import __version__, check_cli, forked
from .escaping import escape_text, json_safe
from .options import TRUE_WORDS


def _graph(args: argparse.Namespace) -> int:
    """The ``graph`` command, with Python's cyclic garbage collector off until it is done: the
    graph and its analysis live until the output is written, and every collection on the way
    would scan all their objects for garbage they do not form (an eighth of the command)."""
    from .analysis import collector_paused

    with collector_paused():
        return _print_graph(args)


def _print_graph(args: argparse.Namespace) -> int:
    from .analysis import analyse, build_graph
    from .launch.api import graph_to_json_obj, system_to_json

    root = Path(args.path)
    if not root.exists():
        print(f"flake8-rosgraph: error: no such file or directory: {args.path}", file=sys.stderr)
        return 2
    stubs = [Path(s) for s in args.stubs]
    # Only --explain reads the analyses themselves: otherwise each is freed once its facts are read.
    graph, analyses = analyse(root, stubs) if args.explain else (build_graph(root, stubs), [])
    for diag in graph.diagnostics:
        if diag.severity == "info" and not args.verbose:
            continue  # kept in the JSON; stderr shows what may change the graph
        where = f"{diag.path}:{diag.line}: " if diag.path else ""
        print(escape_text(f"{where}{diag.severity}: {diag.message}"), file=sys.stderr)
    if args.explain:
        _explain_gaps(graph, analyses, args.verbose)
    system = None
    if args.launch:
        system = _find_system(graph, root, Path(args.launch))
        if system is None:
            print(f"flake8-rosgraph: error: {args.launch} is not a launch file of {args.path}",
                  file=sys.stderr)
            return 2
        for problem in sorted(set(system.problems)):  # what the system may lack, said
            print(escape_text(f"{problem.path}:{problem.line}: {problem.severity}: {problem.message}"),
                  file=sys.stderr)
        if not system.complete:
            unresolved = sum(1 for n in system.nodes if n.unresolved)
            print(escape_text(f"flake8-rosgraph: {args.launch} is not fully followed: "
                              f"{len(set(system.problems))} construct(s) not followed, "
                              f"{unresolved} node(s) with unknown values"), file=sys.stderr)
    if args.format == "json":
        if system is not None:
            from .render import launched_only
            shown = launched_only(graph, system)
            shown.diagnostics = sorted(set(graph.diagnostics) | set(system.problems))
            obj = graph_to_json_obj(shown)
        else:
            obj = graph_to_json_obj(graph)
            obj["systems"] = [system_to_json(s) for s in graph.systems]
        text = json_safe(json.dumps(obj, indent=1, ensure_ascii=False)) + "\n"
    else:
        from .render import Renderer, launched_only
        renderer = Renderer(root, graph)
        if args.format == "html":
            text = renderer.html(system)
        else:
            shown = launched_only(graph, system) if system is not None else graph
            text = renderer.dot(shown) if args.format == "dot" else renderer.mermaid(shown)
    if args.output:
        try:
            Path(args.output).write_text(text, encoding="utf-8", errors="surrogateescape")
        except OSError as exc:
            raise check_cli.UserError(f"cannot write {args.output}: {exc.strerror or exc}") from exc
    else:
        sys.stdout.write(text)
    return 0


def _explain_gaps(graph, analyses, verbose: bool) -> None:
    """Creation sites missing from the graph or known only partly, one line each (stderr)."""
    from .explain import explain
    if not analyses:
        print("flake8-rosgraph: --explain: the analysis did not complete; nothing to explain",
              file=sys.stderr)
        return
    report = explain(analyses, graph)
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


def _rules(args: argparse.Namespace) -> int:
    from .rules import RULES

    rows = [(r.code, r.name, r.level, "on" if r.default_enabled else "off", r.summary) for r in RULES]
    if args.format == "json":
        keys = ("code", "name", "level", "default", "summary")
        print(json.dumps([dict(zip(keys, row)) for row in rows], indent=1))
        return 0
    widths = [max(len(row[i]) for row in rows + [("code", "name", "level", "default", "")]) for i in range(4)]
    print("  ".join(title.ljust(width) for title, width in zip(("code", "name", "level", "default"), widths))
          + "  fires when")
    for row in rows:
        print("  ".join(cell.ljust(width) for cell, width in zip(row, widths)) + "  " + row[4])
    return 0


def _explain_rule(args: argparse.Namespace) -> int:
    from .rules import RULES
    from .rules.docs import rule_doc

    code = args.code.strip().upper()
    rule = next((r for r in RULES if r.code == code or r.name == args.code.strip()), None)
    if rule is None:
        known = ", ".join(r.code for r in RULES)
        print(f"flake8-rosgraph explain: unknown rule '{args.code}' (known: {known})", file=sys.stderr)
        return 2
    doc = rule_doc(rule)
    state = "enabled" if doc.default_enabled else "disabled (opt in with --extend-select " + doc.code + ")"
    print(f"# {doc.code} {doc.name}\n\nLevel: {doc.level}; {state} by default.\n\n{doc.summary}\n")
    print(doc.markdown)
    return 0


def make_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="flake8-rosgraph",
                                     description="Static ROS 2 computation graph of rclpy code.")
    parser.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    sub = parser.add_subparsers(dest="command", required=True)
    graph = sub.add_parser("graph", help="print the ROS computation graph of PATH")
    graph.add_argument("path", help="workspace folder (or a single file)")
    graph.add_argument("--format", choices=("json", "dot", "mermaid", "html"), default="json",
                       help="json (contract rosgraph/1), dot (Graphviz), mermaid (Markdown, pull requests) "
                            "or html (one self-contained interactive page)")
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
                       help="show only the system this launch file starts (names, namespaces and "
                            "remappings applied) instead of the code-level graph")
    check_cli.add_jobs_argument(graph)
    graph.set_defaults(run=_graph)
    check_cli.add_parser(sub)
    rules = sub.add_parser("rules", help="list the rules: code, name, level, enabled by default")
    rules.add_argument("--format", choices=("text", "json"), default="text")
    rules.set_defaults(run=_rules)
    explain = sub.add_parser("explain", help="print a rule's documentation (what, why, example, fix)")
    explain.add_argument("code", help="rule code (ROS003) or name (subscription-without-publisher)")
    explain.set_defaults(run=_explain_rule)
    return parser


def main(argv: list[str] | None = None) -> int:
    parser = make_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:
        return int(exc.code or 0) and 2
    try:
        with forked.processes(getattr(args, "jobs", None) or forked.cores()):
            return args.run(args)
    except BrokenPipeError:  # the reader went away (``| head``): not an error of ours
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    except Exception as exc:  # one clear line; the traceback only when asked for
        if getattr(args, "debug", False) or os.environ.get("ROSGRAPH_DEBUG", "").strip().lower() in TRUE_WORDS:
            traceback.print_exc()
        if isinstance(exc, check_cli.UserError):
            print(escape_text(f"flake8-rosgraph: error: {exc}"), file=sys.stderr)
        else:
            print(escape_text(f"flake8-rosgraph: internal error: {type(exc).__name__}: {exc}"), file=sys.stderr)
        return 2
