"""``flake8-rosgraph check PATH``: the graph rules without flake8.

It reports what the flake8 plugin reports for the same files: the findings of
each PATH's workspace (found as in :mod:`.root`, or ``--root``) located in the
files under PATH (and, for a broken connection whose own end is outside every
PATH, a copy at its other end under PATH: :mod:`.partial_runs`), with ``# noqa`` comments honoured as flake8 honours them and
the off-by-default rules opted in the same way (``--select ROS010``). The same
environment variables apply (``ROSGRAPH_ROOT``, ``ROSGRAPH_STUBS``, …); command
line flags win over them. It shares the workspace cache with the plugin.

Exit status: 0 no findings, 1 findings, 2 usage or internal error.
"""
from __future__ import annotations

import argparse
import io
import json
import os
import sys
import tokenize
from pathlib import Path
from typing import Any

from .cache import workspace_report
from .graph.model import Diagnostic
from .options import INTERNAL_ERROR_CODE, CodeFilter, Settings
from .root import discover_root, find_vcs_root
from .findings import Finding
from .partial_runs import shown_findings

EXIT_CLEAN, EXIT_FINDINGS, EXIT_ERROR = 0, 1, 2
CHECK_CATEGORY = "flake8-rosgraph/check"


def add_parser(subparsers: Any) -> None:
    """Register the ``check`` subcommand on the main CLI's subparsers."""
    parser = subparsers.add_parser(
        "check", help="run the ROS graph rules without flake8",
        description="Run the ROS graph rules on the workspace of each PATH and print the findings "
                    "located under PATH. Exit status: 0 clean, 1 findings, 2 usage or internal error.",
    )
    parser.add_argument("paths", nargs="+", type=Path, metavar="PATH",
                        help="files or directories whose findings to report")
    parser.add_argument("--format", choices=("text", "json"), default="text", help="terminal output format")
    parser.add_argument("--sarif", type=Path, metavar="FILE", help="also write the findings as SARIF 2.1.0")
    parser.add_argument("--root", type=Path, help="workspace root (default: discovered; env ROSGRAPH_ROOT)")
    parser.add_argument("--stubs", metavar="FILES", help="comma-separated extra library model files")
    parser.add_argument("--external-topics", metavar="NAMES",
                        help="comma-separated names used outside the workspace")
    parser.add_argument("--cache-dir", type=Path, help="cache location (default: <root>/.rosgraph-cache)")
    parser.add_argument("--select", metavar="CODES", help="comma-separated code prefixes to report")
    parser.add_argument("--extend-select", metavar="CODES", help="code prefixes to report in addition")
    parser.add_argument("--ignore", metavar="CODES", help="comma-separated code prefixes not to report")
    parser.add_argument("--debug", action="store_true", help="re-raise internal errors (env ROSGRAPH_DEBUG)")
    parser.set_defaults(run=run)


def _codes(value: str | None) -> list[str]:
    return [c.strip().upper() for c in (value or "").split(",") if c.strip()]


def _noqa_lines(path: Path) -> dict[int, str]:
    """Line → the text flake8 searches for ``# noqa`` (a multi-line string counts as one line)."""
    try:
        source = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return {}
    lines = source.splitlines(keepends=True)
    mapping = {number: line for number, line in enumerate(lines, 1)}
    try:
        tokens = list(tokenize.generate_tokens(io.StringIO(source).readline))
    except (tokenize.TokenError, SyntaxError):
        return mapping
    first, last = len(lines) + 2, -1
    for token in tokens:
        if token.type == tokenize.ENDMARKER:
            break
        first, last = min(first, token.start[0]), max(last, token.end[0])
        if token.type in (tokenize.NL, tokenize.NEWLINE):
            joined = "".join(lines[first - 1:last])
            mapping.update(dict.fromkeys(range(first, last + 1), joined))
            first, last = len(lines) + 2, -1
    return mapping


def _noqa_suppresses(line: str | None, code: str) -> bool:
    from flake8.defaults import NOQA_INLINE_REGEXP

    match = NOQA_INLINE_REGEXP.search(line or "")
    if match is None:
        return False
    codes = match.groupdict()["codes"]
    if codes is None:
        return True
    listed = tuple(c for c in codes.replace(",", " ").split() if c)
    return code.startswith(listed)


class _Selection:
    """``--select``/``--extend-select``/``--ignore`` over ROS codes, as in flake8 (longest match wins)."""

    def __init__(self, args: argparse.Namespace, rules: Any) -> None:
        self.select = (_codes(args.select) or ["ROS"]) + _codes(args.extend_select)
        self.ignore = _codes(args.ignore)
        self.codes = CodeFilter.build(_codes(args.select) + _codes(args.extend_select), rules)

    def __call__(self, code: str) -> bool:
        selected = max((len(s) for s in self.select if code.startswith(s)), default=-1)
        ignored = max((len(s) for s in self.ignore if code.startswith(s)), default=-1)
        return selected > ignored and self.codes(code)


def _settings(args: argparse.Namespace) -> Settings:
    given = {"root": args.root, "stubs": args.stubs, "external_topics": args.external_topics,
             "sarif": args.sarif, "cache_dir": args.cache_dir, "debug": args.debug}
    return Settings.resolve({k: (str(v) if isinstance(v, Path) else v) for k, v in given.items()}, os.environ)


def _is_under(path: Path, target: Path) -> bool:
    return path == target or target in path.parents


def _collect(settings: Settings, paths: list[Path], wanted: _Selection
             ) -> tuple[list[tuple[Path, Finding]], list[tuple[Path, Diagnostic]]]:
    findings: set[tuple[Path, Finding]] = set()
    diagnostics: set[tuple[Path, Diagnostic]] = set()
    targets_by_root: dict[Path, list[Path]] = {}
    for target in (Path(os.path.abspath(p)) for p in paths):
        root = Path(os.path.abspath(settings.root)) if settings.root else discover_root(target)
        targets_by_root.setdefault(root, []).append(target)
    for root, targets in sorted(targets_by_root.items()):
        report = workspace_report(root, settings)
        diagnostics.update((root, d) for d in report.diagnostics)

        def checked(path: str, root: Path = root, targets: list[Path] = targets) -> bool:
            return any(_is_under(root / path, target) for target in targets)

        noqa: dict[Path, dict[int, str]] = {}
        for finding in shown_findings(report.findings, checked):
            path = root / finding.location.path
            if not wanted(finding.code):
                continue
            if path not in noqa:
                noqa[path] = _noqa_lines(path)
            if not _noqa_suppresses(noqa[path].get(finding.location.line), finding.code):
                findings.add((root, finding))
    return (sorted(findings, key=lambda rf: (str(rf[0] / rf[1].location.path), rf[1])),
            sorted(diagnostics, key=lambda rd: (str(rd[0]), rd[1])))


def _display(path: Path) -> str:
    """A path as the user would type it: relative to the current directory when inside it."""
    try:
        return path.relative_to(Path.cwd()).as_posix()
    except ValueError:
        return path.as_posix()


def _json(findings: list[tuple[Path, Finding]], diagnostics: list[tuple[Path, Diagnostic]]) -> str:
    def where(root: Path, location: Any) -> dict[str, Any]:
        return {"path": _display(root / location.path), "line": location.line, "column": location.column}

    data = {
        "findings": [
            {"code": f.code, "message": f.message, **where(root, f.location),
             "related": [{**where(root, loc), "label": label} for loc, label in f.related]}
            for root, f in findings
        ],
        "diagnostics": [
            {"path": _display(root / d.path), "line": d.line, "message": d.message, "severity": d.severity}
            for root, d in diagnostics
        ],
    }
    return json.dumps(data, indent=2, ensure_ascii=False)


def _write_sarif(target: Path, findings: list[tuple[Path, Finding]],
                 diagnostics: list[tuple[Path, Diagnostic]], fallback_root: Path) -> None:
    from . import sarif

    roots = sorted({root for root, _ in findings} | {root for root, _ in diagnostics}) or [fallback_root]
    log = sarif.sarif_log(
        (sarif.finding_problem(root, f) for root, f in findings), sarif.catalogue(),
        srcroot=find_vcs_root(roots[0]) or roots[0], category=CHECK_CATEGORY, diagnostics=diagnostics,
    )
    sarif.write(target, log)


def run(args: argparse.Namespace) -> int:
    """Run the check; print findings; return the exit status."""
    settings = _settings(args)
    missing = [str(p) for p in args.paths if not p.exists()]
    if missing:
        print(f"flake8-rosgraph check: no such file or directory: {', '.join(missing)}", file=sys.stderr)
        return EXIT_ERROR
    try:
        from .rules import RULES

        findings, diagnostics = _collect(settings, list(args.paths), _Selection(args, RULES))
        if settings.sarif is not None:
            _write_sarif(settings.sarif, findings, diagnostics, Path(os.path.abspath(args.paths[0])))
    except Exception as exc:
        if settings.debug:
            raise
        print(f"flake8-rosgraph check: {INTERNAL_ERROR_CODE} internal error ({type(exc).__name__}: {exc}); "
              "rerun with --debug for the traceback", file=sys.stderr)
        return EXIT_ERROR
    if args.format == "json":
        print(_json(findings, diagnostics))
    else:
        for root, f in findings:
            loc = f.location
            print(f"{_display(root / loc.path)}:{loc.line}:{loc.column}: {f.code} {f.message}")
    # An error diagnostic (broken stub, an error the analysis caught) means an
    # incomplete graph, whose silence proves nothing: that is not a clean run.
    errors = [(root, d) for root, d in diagnostics if d.severity == "error"]
    for root, d in errors:
        where = f"{_display(root / d.path)}:{d.line}: " if d.path else ""
        print(f"flake8-rosgraph check: {INTERNAL_ERROR_CODE} {where}{d.message}", file=sys.stderr)
    if errors:
        return EXIT_ERROR
    return EXIT_FINDINGS if findings else EXIT_CLEAN
