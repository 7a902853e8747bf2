"""``flake8-rosgraph check PATH``: the graph rules without flake8.

It reports what the flake8 plugin reports for the same files: the findings of
each PATH's workspace (found as in :mod:`.root`, or ``--root``) located in the
files under PATH (and, for a broken connection whose own end is outside every
PATH, a copy at its other end under PATH: :mod:`.partial_runs`), with ``# noqa`` comments honoured as flake8 honours them and
the off-by-default rules opted in the same way (``--select ROS010``). The same
environment variables apply (``ROSGRAPH_ROOT``, ``ROSGRAPH_STUBS``, …); command
line flags win over them. It shares the workspace cache with the plugin.

It reads the configuration the plugin reads (:mod:`.config`: ``[flake8]`` in
``setup.cfg``/``tox.ini``/``.flake8``, plus ``[tool.flake8-rosgraph]`` in
``pyproject.toml``), including ``per-file-ignores`` and ``# flake8: noqa``
file markers. ``--baseline FILE`` hides the findings recorded by
``--write-baseline FILE`` (matched by fingerprint, so they survive line
shifts), to adopt the tool on a workspace with old findings.

Exit status: 0 no findings (or ``--exit-zero``), 1 findings, 2 usage or internal error.
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
from .config import ConfigError, FileConfig, load_config
from .escaping import escape_text, json_safe
from .findings import Finding, display_path, localised_message
from .fingerprints import Ranks, SourceLines, finding_fingerprint, without_line_numbers
from .graph.model import Diagnostic
from .options import INTERNAL_ERROR_CODE, CodeFilter, Settings, root_problem
from .root import RootRefused, discover_root, find_vcs_root
from .partial_runs import shown_findings
from .safe_io import MAX_SOURCE_BYTES, read_text

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
    parser.add_argument("--format", choices=("text", "json", "github"), default="text",
                        help="terminal output: text (path:line:col: CODE message), json, or github "
                             "(workflow commands that annotate a pull request)")
    parser.add_argument("--sarif", type=Path, metavar="FILE", help="also write the findings as SARIF 2.1.0")
    parser.add_argument("--root", type=Path, help="workspace root (default: discovered; env ROSGRAPH_ROOT)")
    parser.add_argument("--stubs", metavar="FILES", help="comma-separated extra library model files")
    parser.add_argument("--interfaces", metavar="DIRS",
                        help="comma-separated folders of interface packages outside the workspace "
                             "(env ROSGRAPH_INTERFACES)")
    parser.add_argument("--external-topics", metavar="NAMES",
                        help="comma-separated names used outside the workspace")
    parser.add_argument("--cache-dir", type=Path, help="cache location (default: <root>/.rosgraph-cache)")
    parser.add_argument("--select", metavar="CODES", help="comma-separated code prefixes to report")
    parser.add_argument("--extend-select", metavar="CODES", help="code prefixes to report in addition")
    parser.add_argument("--ignore", metavar="CODES", help="comma-separated code prefixes not to report")
    parser.add_argument("--debug", action="store_true", help="re-raise internal errors (env ROSGRAPH_DEBUG)")
    add_jobs_argument(parser)
    parser.add_argument("--exit-zero", action="store_true", help="exit 0 even when there are findings")
    parser.add_argument("--baseline", type=Path, metavar="FILE",
                        help="do not report the findings recorded in FILE (see --write-baseline)")
    parser.add_argument("--write-baseline", type=Path, metavar="FILE",
                        help="record the current findings in FILE (then adopt with --baseline FILE)")
    parser.set_defaults(run=run)


def add_jobs_argument(parser: Any) -> None:
    """``--jobs N``: the processes the analysis may use (groups of modules analysed side by side)."""
    parser.add_argument("--jobs", "-j", type=_positive, metavar="N",
                        help="processes the analysis may use (default: one per CPU)")


def _positive(value: str) -> int:
    number = int(value)
    if number < 1:
        raise ValueError(value)
    return number


def _codes(value: str | None) -> list[str]:
    return [c.strip().upper() for c in (value or "").split(",") if c.strip()]


def _noqa_lines(source: str) -> dict[int, str]:
    """Line → the text flake8 searches for ``# noqa`` (a multi-line string counts as one line)."""
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
    """``--select``/``--extend-select``/``--ignore`` over ROS codes, as in flake8 (longest match wins).

    A flag given on the command line wins over the configuration files' value. The files
    are shared with flake8 and its other plugins: of their codes only this tool's count
    (``ROS…``), so ``select = E,F,W`` or ``extend-ignore = E203`` there leave the ROS rules
    as they are by default.
    """

    def __init__(self, args: argparse.Namespace, rules: Any, config: FileConfig) -> None:
        def configured(name: str) -> list[str]:
            return [code for code in config.values.get(name, []) if _is_ours(code)]

        def pick(name: str) -> list[str]:
            given = _codes(getattr(args, name))
            return given if given else configured(name)

        select, extend = pick("select"), pick("extend_select")
        self.select = (select or ["ROS"]) + extend
        self.ignore = pick("ignore") + configured("extend_ignore")
        self.codes = CodeFilter.build(select + extend, rules)
        self.given = select + extend + self.ignore

    def unknown(self, rules: Any) -> list[str]:
        """Given codes that name no rule of this tool (``ROS999``, ``ROS01X``): a typo that selects nothing.

        flake8 rejects a malformed code; on this tool's command line every code is
        one of ours, so an entry that is not a prefix of any rule code is refused, and
        so is a ``ROS…`` code of a configuration file that names no rule.
        """
        codes = [rule.code for rule in rules] + [INTERNAL_ERROR_CODE]
        return sorted({c for c in self.given if not any(code.startswith(c) for code in codes)})

    def __call__(self, code: str) -> bool:
        selected = max((len(s) for s in self.select if code.startswith(s)), default=-1)
        ignored = max((len(s) for s in self.ignore if code.startswith(s)), default=-1)
        return selected > ignored and self.codes(code)


#: What every code of this tool starts with.
_CODE_PREFIX = "ROS"


def _is_ours(code: str) -> bool:
    """Whether a code of a shared configuration file is meant for this tool (``ROS``,
    ``ROS1``, ``ROS107``; ``R`` and ``RO`` select it too)."""
    return bool(code) and (code.startswith(_CODE_PREFIX) or _CODE_PREFIX.startswith(code))


class UserError(Exception):
    """A mistake in the command line, the configuration or the environment: one line, exit status 2."""


def _check_root(settings: Settings, args: argparse.Namespace) -> None:
    """A given root must be an existing folder holding the checked paths (``UserError`` otherwise)."""
    problem = root_problem(settings.root, "--root", args)
    if problem is not None:
        raise UserError(problem)
    if settings.root is None:
        return
    root = Path(os.path.abspath(settings.root))
    outside = [str(p) for p in args.paths if not _is_under(Path(os.path.abspath(p)), root)]
    if outside:
        raise UserError(f"{', '.join(outside)}: not inside the workspace root {settings.root}")


def _settings(args: argparse.Namespace, config: FileConfig) -> Settings:
    """Command line first, then the configuration files, then the environment."""
    given = {"root": args.root, "stubs": args.stubs, "external_topics": args.external_topics,
             "sarif": args.sarif, "cache_dir": args.cache_dir, "debug": args.debug or None,
             "interfaces": args.interfaces}
    merged = {key: (str(value) if isinstance(value, Path) else value) if value is not None
              else config.values.get(key) for key, value in given.items()}
    return Settings.resolve(merged, os.environ)


def _skips_file(source: str) -> bool:
    """Whether flake8 skips the whole file (a line that is only ``# flake8: noqa``)."""
    from flake8.defaults import NOQA_FILE

    return any(NOQA_FILE.match(line) for line in source.splitlines())


class _Noqa:
    """``# noqa`` comments and ``# flake8: noqa`` file markers, each file read once."""

    def __init__(self) -> None:
        self._lines: dict[Path, dict[int, str] | None] = {}  # None: the whole file is skipped

    def hides(self, path: Path, line: int, code: str) -> bool:
        if path not in self._lines:
            try:
                source = read_text(path, None, MAX_SOURCE_BYTES)
            except (OSError, UnicodeDecodeError):
                source = ""
            self._lines[path] = None if _skips_file(source) else _noqa_lines(source)
        lines = self._lines[path]
        return lines is None or _noqa_suppresses(lines.get(line), code)


def _is_under(path: Path, target: Path) -> bool:
    return path == target or target in path.parents


def _collect(settings: Settings, paths: list[Path], wanted: _Selection, config: FileConfig
             ) -> tuple[list[tuple[Path, Finding]], list[tuple[Path, Diagnostic]]]:
    findings: set[tuple[Path, Finding]] = set()
    diagnostics: set[tuple[Path, Diagnostic]] = set()
    targets_by_root: dict[Path, list[Path]] = {}
    for target in (Path(os.path.abspath(p)) for p in paths):
        try:
            root = Path(os.path.abspath(settings.root)) if settings.root else discover_root(target)
        except RootRefused as refused:
            raise UserError(str(refused)) from None
        targets_by_root.setdefault(root, []).append(target)
    for root, targets in sorted(targets_by_root.items()):
        report = workspace_report(root, settings)
        base = root if root.is_dir() else root.parent  # a lone file is its own root
        diagnostics.update((base, d) for d in report.diagnostics)

        def checked(path: str, base: Path = base, targets: list[Path] = targets) -> bool:
            return any(_is_under(base / path, target) for target in targets)

        noqa = _Noqa()
        for finding in shown_findings(report.findings, checked):
            path = base / finding.location.path
            if not wanted(finding.code) or config.ignored_in(path, finding.code):
                continue
            if not noqa.hides(path, finding.location.line, finding.code):
                findings.add((base, finding))
    return (sorted(findings, key=lambda rf: (str(rf[0] / rf[1].location.path), rf[1])),
            sorted(diagnostics, key=lambda rd: (str(rd[0]), rd[1])))


def _json(findings: list[tuple[Path, Finding]], diagnostics: list[tuple[Path, Diagnostic]]) -> str:
    def where(root: Path, location: Any) -> dict[str, Any]:
        return {"path": display_path(root / location.path), "line": location.line, "column": location.column}

    data = {
        "findings": [
            {"code": f.code, "message": localised_message(root, f), **where(root, f.location),
             "related": [{**where(root, loc), "label": label} for loc, label in f.related]}
            for root, f in findings
        ],
        "diagnostics": [
            {"path": display_path(root / d.path), "line": d.line, "message": d.message, "severity": d.severity}
            for root, d in diagnostics
        ],
    }
    return json_safe(json.dumps(data, indent=2, ensure_ascii=False))


def _write_sarif(target: Path, findings: list[tuple[Path, Finding]],
                 diagnostics: list[tuple[Path, Diagnostic]], fallback_root: Path, successful: bool) -> None:
    from . import sarif

    roots = sorted({root for root, _ in findings} | {root for root, _ in diagnostics}) or [fallback_root]
    log = sarif.sarif_log(
        (sarif.finding_problem(root, f) for root, f in findings), sarif.catalogue(),
        srcroot=find_vcs_root(roots[0]) or roots[0], category=CHECK_CATEGORY, diagnostics=diagnostics,
        successful=successful,
    )
    sarif.write(target, log)


BASELINE_SCHEMA = "flake8-rosgraph-baseline/1"
#: GitHub workflow command for each rule level.
_GITHUB_LEVEL = {"error": "error", "warning": "warning", "note": "notice"}


def _fingerprints(findings: list[tuple[Path, Finding]]) -> list[str]:
    """Each finding's identity (see :mod:`.fingerprints`), in the order given."""
    lines, ranks, out = SourceLines(), Ranks(), []
    for root, f in findings:
        text = lines.text(root / f.location.path, f.location.line)
        rank = ranks.next((str(root), f.code, f.location.path, without_line_numbers(f.message), text))
        out.append(finding_fingerprint(f.code, f.location.path, f.message, text, rank,
                                       [(loc.path, label) for loc, label in f.related]))
    return out


def _read_baseline(path: Path) -> set[str]:
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
        if data.get("schema") != BASELINE_SCHEMA:
            raise ValueError(f"not a {BASELINE_SCHEMA} file")
        return {entry["fingerprint"] for entry in data["findings"]}
    except (OSError, UnicodeDecodeError, ValueError, KeyError, TypeError, AttributeError) as exc:
        raise ConfigError(f"{path}: cannot read the baseline: {exc}") from None


def _write_baseline(path: Path, findings: list[tuple[Path, Finding]], prints: list[str]) -> None:
    entries = [{"fingerprint": fp, "code": f.code, "path": f.location.path, "message": f.message}
               for (_, f), fp in zip(findings, prints)]
    entries.sort(key=lambda e: (e["path"], e["code"], e["message"], e["fingerprint"]))
    text = json.dumps({"schema": BASELINE_SCHEMA, "findings": entries}, indent=1, ensure_ascii=False) + "\n"
    path.write_text(text, encoding="utf-8")


def _github_escape(text: str, property_value: bool = False) -> str:
    """GitHub workflow command escaping (data: ``%``, CR, LF; property values also ``:`` and ``,``)."""
    text = text.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")
    return text.replace(":", "%3A").replace(",", "%2C") if property_value else text


def _print_findings(args: argparse.Namespace, findings: list[tuple[Path, Finding]],
                    diagnostics: list[tuple[Path, Diagnostic]]) -> None:
    if args.format == "json":
        print(_json(findings, diagnostics))
        return
    if args.format == "github":
        from .rules import RULES

        levels = {rule.code: rule.level for rule in RULES}
        for root, f in findings:
            loc = f.location
            props = ",".join(f"{key}={_github_escape(str(value), True)}" for key, value in (
                ("file", display_path(root / loc.path)), ("line", loc.line), ("col", loc.column), ("title", f.code)))
            print(escape_text(f"::{_GITHUB_LEVEL.get(levels.get(f.code, 'warning'), 'warning')} {props}::"
                              f"{_github_escape(f.code + ' ' + localised_message(root, f))}"))
        return
    for root, f in findings:
        loc = f.location
        print(escape_text(f"{display_path(root / loc.path)}:{loc.line}:{loc.column}: "
                          f"{f.code} {localised_message(root, f)}"))


def run(args: argparse.Namespace) -> int:
    """Run the check; print findings; return the exit status."""
    settings = Settings()
    try:
        try:
            config = load_config(Path.cwd())
        except ConfigError as exc:
            raise UserError(str(exc)) from None
        settings = _settings(args, config)
        missing = [str(p) for p in args.paths if not p.exists()]
        if missing:
            raise UserError(f"no such file or directory: {', '.join(missing)}")
        from .rules import RULES

        wanted = _Selection(args, RULES, config)
        unknown = wanted.unknown(RULES)
        if unknown:
            raise UserError(f"unknown rule code(s): {', '.join(unknown)} "
                            f"(codes: {', '.join(rule.code for rule in RULES)})")
        _check_root(settings, args)
        baseline_file = args.baseline or (Path(config.values["baseline"]) if "baseline" in config.values else None)
        try:
            baseline = _read_baseline(baseline_file) if baseline_file is not None else set()
        except ConfigError as exc:
            raise UserError(str(exc)) from None
        findings, diagnostics = _collect(settings, list(args.paths), wanted, config)
        prints = _fingerprints(findings)
        if args.write_baseline is not None:
            try:
                _write_baseline(args.write_baseline, findings, prints)
            except OSError as exc:
                raise UserError(f"cannot write the baseline {args.write_baseline}: {exc.strerror or exc}") from exc
        findings = [pair for pair, fp in zip(findings, prints) if fp not in baseline]
        # An error diagnostic (broken stub, an error the analysis caught) means an
        # incomplete graph, whose silence proves nothing: that is not a clean run.
        errors = [(root, d) for root, d in diagnostics if d.severity == "error"]
        if settings.sarif is not None:
            try:
                _write_sarif(settings.sarif, findings, diagnostics, Path(os.path.abspath(args.paths[0])),
                             successful=not errors)
            except OSError as exc:
                raise UserError(f"cannot write the SARIF file {settings.sarif}: {exc.strerror or exc}") from exc
    except UserError as exc:
        if settings.debug:
            raise
        print(escape_text(f"flake8-rosgraph check: error: {exc}"), file=sys.stderr)
        return EXIT_ERROR
    except Exception as exc:
        if settings.debug:
            raise
        print(escape_text(f"flake8-rosgraph check: {INTERNAL_ERROR_CODE} internal error "
                          f"({type(exc).__name__}: {exc}); rerun with --debug for the traceback"),
              file=sys.stderr)
        return EXIT_ERROR
    _print_findings(args, findings, diagnostics)
    for root, d in errors:
        where = f"{display_path(root / d.path)}:{d.line}: " if d.path else ""
        print(escape_text(f"flake8-rosgraph check: {INTERNAL_ERROR_CODE} {where}{d.message}"), file=sys.stderr)
    if errors:
        return EXIT_ERROR
    return EXIT_FINDINGS if findings and not args.exit_zero else EXIT_CLEAN
