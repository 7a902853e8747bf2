"""The flake8 adapter: options, the per-file view of workspace findings, the report-stage hook.

flake8 hands the checker one file at a time; the checker finds the file's
workspace (:mod:`.root`), gets that workspace's findings (analysed once per run
and shared between worker processes through :mod:`.cache`) and yields those
located in this file (when flake8 checks only some files, also the broken
connections whose other end is here: :mod:`.partial_runs`). flake8 then applies ``# noqa``, ``--select``/``--ignore``
and ``--per-file-ignores`` as for any plugin.

With ``--jobs`` above 1 the workers' checkers report nothing: the main process
analyses beside them and adds each file's results before the report stage (see
:mod:`.flake8_jobs`). When ``--select``/``--ignore`` leave no ROS code, nothing is
analysed at all.

The checker never raises: an internal error becomes a ``ROS000`` finding at
line 1 (``--rosgraph-debug`` / ``ROSGRAPH_DEBUG=1`` re-raises instead). A
workspace-level failure would hit every checked file, so the report hook keeps
the first ``ROS000`` of each message and drops the repeats.

The report hook wraps ``flake8.checker.Manager.report`` (present, with the same
``style_guide.handle_error`` protocol, in flake8 4.0.1 … 7.x). It sees every
result after flake8's filters, in flake8's deterministic order, in the main
process, whatever formatter the user picked, and writes the ``--rosgraph-sarif``
sidecar from it. A ``flake8.report`` formatter could not do this: flake8 runs a
single formatter, so it would replace the user's terminal output.
"""
from __future__ import annotations

import ast
import functools
import itertools
import os
import re
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Iterator

from . import __version__, flake8_jobs, forked
from .cache import WorkspaceReport, kept_state, start_run, workspace_report
from .codes import RULE_CODES
from .escaping import escape_text
from .options import (INTERNAL_ERROR_CODE, CodeFilter, Settings, flake8_selectors, register_flake8_options,
                      root_problem)
from .root import RootRefused, discover_root, find_vcs_root
from .findings import Finding, localised_message
from .partial_runs import CONNECTION_CODES, CheckedFiles, shown_findings

#: A flake8 plugin entry name that is a code prefix (``E``, ``F``, ``ROS``).
_CODE_PREFIX = re.compile(r"^[A-Z]{1,3}[0-9]{0,3}$")
SIDECAR_CATEGORY = "flake8-rosgraph/flake8"


@dataclass(frozen=True)
class _Run:
    """What ``parse_options`` learnt about the current flake8 run."""

    settings: Settings
    codes: CodeFilter
    #: Why the options could not be used, reported as ROS000 on each checked file.
    error: str | None = None
    #: Whether flake8 could report any ROS code at all (``--select E,W``: no analysis).
    selected: bool = True
    #: Folder of a checked file → its workspace root, or why no root was taken there.
    roots: dict[Path, Path | RootRefused] = field(default_factory=dict, compare=False)
    #: flake8 reads the checked file from standard input (``flake8 -``): an editor's unsaved buffer.
    stdin: bool = False
    #: That buffer, once the checker has seen it (absolute path → bytes); the report stage reuses it.
    buffers: dict[str, bytes] = field(default_factory=dict, compare=False)
    #: The files this run checks; ``None`` when flake8 does not tell (then every file counts as checked).
    checked: CheckedFiles | None = None
    #: The folders named on flake8's command line (the current one for ``flake8`` alone and for
    #: an editor's buffer): a root without a workspace marker never reaches beyond them.
    given: tuple[Path, ...] = ()

    @functools.cached_property
    def given_root(self) -> Path:
        """``--rosgraph-root`` made absolute: once per run rather than once per checked file."""
        assert self.settings.root is not None
        return Path(os.path.abspath(self.settings.root))


_RUN: _Run | None = None


def _describe(exc: BaseException) -> str:
    detail = str(exc).strip().splitlines()
    return f"{type(exc).__name__}: {detail[0][:200]}" if detail else type(exc).__name__


def _internal_error_text(description: str) -> str:
    return (f"{INTERNAL_ERROR_CODE} flake8-rosgraph internal error ({description}); "
            "rerun with --rosgraph-debug or ROSGRAPH_DEBUG=1 for the traceback")


def _analysis_error_text(description: str) -> str:
    return f"{INTERNAL_ERROR_CODE} flake8-rosgraph could not analyse everything, findings may be missing: {description}"


def _current_run() -> _Run:
    """The run ``parse_options`` set up; flake8 always calls it, but be safe if it did not."""
    if _RUN is not None:
        return _RUN
    return _Run(Settings.resolve({}, os.environ), CodeFilter.build((), RULE_CODES))


def _root_for(run: _Run, path: Path) -> Path:
    if run.settings.root is not None:
        return run.given_root
    directory = path.parent
    if directory not in run.roots:
        try:
            holders = [folder for folder in run.given if folder == directory or folder in directory.parents]
            root = discover_root(path, min(holders, key=lambda folder: len(folder.parts), default=None))
        except RootRefused as refused:  # probed once per folder, not once per file
            run.roots[directory] = refused
            raise
        if root == path:  # a lone file that is its own root says nothing about its neighbours
            return root
        run.roots[directory] = root
    known = run.roots[directory]
    if isinstance(known, RootRefused):
        raise known
    return known


def _per_report(build: Callable[[WorkspaceReport], Any]) -> Callable[[WorkspaceReport], Any]:
    """Memoise ``build`` per report object (the last few). Not by value, as ``lru_cache``
    would: hashing every finding of the workspace again on every checked file cost more than
    the lookup it saved. The memo holds the report, so its ``id`` cannot be reused meanwhile."""
    memo: dict[int, tuple[WorkspaceReport, Any]] = {}

    @functools.wraps(build)
    def cached(report: WorkspaceReport) -> Any:
        hit = memo.get(id(report))
        if hit is None:
            if len(memo) >= 8:
                memo.clear()
            hit = memo[id(report)] = (report, build(report))
        return hit[1]
    return cached


@_per_report
def _by_file(report: WorkspaceReport) -> dict[str, list[Finding]]:
    index: dict[str, list[Finding]] = {}
    for finding in report.findings:
        index.setdefault(finding.location.path, []).append(finding)
    return index


@_per_report
def _by_other_end(report: WorkspaceReport) -> dict[str, list[Finding]]:
    """Broken-connection findings by the files of their other ends (see :mod:`.partial_runs`)."""
    index: dict[str, list[Finding]] = {}
    for finding in report.findings:
        if finding.code in CONNECTION_CODES:
            for path in sorted({loc.path for loc, _ in finding.related} - {finding.location.path}):
                index.setdefault(path, []).append(finding)
    return index


def _relative(path: Path, root: Path) -> str | None:
    prefix, text = os.path.join(str(root), ""), str(path)
    if len(text) > len(prefix) and text.startswith(prefix):  # the common case, without pathlib's parsing
        return text[len(prefix):].replace(os.sep, "/")
    if root.is_file():  # a lone file is its own root; its findings are named relative to its folder
        root = root.parent
    try:
        return path.relative_to(root).as_posix()
    except ValueError:
        pass
    try:  # through links: resolved only when the plain paths do not nest (a stat per part)
        return path.resolve().relative_to(root.resolve()).as_posix()
    except ValueError:
        return None


#: The last answer of :func:`_file_report` as ``[run, (filename, buffers), answer]``: the checker
#: asks for a file's findings and then for the analysis's errors, one right after the other.
_LAST_FILE: list[Any] = []


def _file_report(run: _Run, filename: str) -> tuple[WorkspaceReport, Path, str] | None:
    buffers = tuple(sorted(run.buffers.items()))
    if _LAST_FILE and _LAST_FILE[0] is run and _LAST_FILE[1] == (filename, buffers):
        return _LAST_FILE[2]
    path = Path(os.path.abspath(filename))
    root = _root_for(run, path)
    relative = _relative(path, root)
    found = None
    if relative is not None:
        with forked.processes(flake8_jobs.analysis_processes()):
            found = (workspace_report(root, run.settings, buffers), root, relative)
    _LAST_FILE[:] = [run, (filename, buffers), found]
    return found


def _note_buffer(run: _Run, filename: str, lines: list[str]) -> None:
    """Under ``flake8 -`` (editors: ``--stdin-display-name PATH``), analyse the buffer instead of the file.

    The buffer replaces the file only when it differs from what is on disk, so a
    saved file keeps using the shared cache.
    """
    if not run.stdin or not lines:
        return
    path = os.path.abspath(filename)
    buffer = "".join(lines).encode("utf-8", errors="surrogateescape")
    try:
        with open(path, "rb") as handle:
            unchanged = handle.read(len(buffer) + 1) == buffer
    except OSError:
        return  # no such file (plain "stdin"): nothing of the workspace to replace
    if not unchanged:
        run.buffers[path] = buffer


def findings_in_file(run: _Run, filename: str) -> list[Finding]:
    """The findings of ``filename``'s workspace shown in ``filename`` and not filtered out.

    Those located there, and, when the run checks only some files, those of
    a broken connection whose other end is here and whose own file is not
    checked (:mod:`.partial_runs`).
    """
    found = _file_report(run, filename)
    if found is None:
        return []
    report, root, relative = found
    own = _by_file(report).get(relative, [])
    if run.checked is None:
        shown = own
    else:
        checked_files = run.checked

        def checked(path: str) -> bool:
            return path == relative or (root / path) in checked_files

        shown = [f for f in shown_findings([*own, *_by_other_end(report).get(relative, [])], checked)
                 if f.location.path == relative]
    return [f for f in shown if run.codes(f.code)]


def analysis_errors(run: _Run, filename: str) -> list[str]:
    """The analysis's error diagnostics (a broken stub, an internal error it caught) of the file's workspace.

    The graph is incomplete then, so the rules' silence proves nothing: each
    becomes a ROS000 on every checked file (the report hook keeps one).
    """
    found = _file_report(run, filename)
    return [] if found is None else list(_error_texts(found[0]))


@_per_report
def _error_texts(report: WorkspaceReport) -> list[str]:
    return [f"{d.path}:{d.line}: {d.message}" if d.path else d.message
            for d in report.diagnostics if d.severity == "error"]


class RosGraphChecker:
    """The ``ROS`` flake8 extension: reports the graph rules' findings in the files they are located in."""

    name = "flake8-rosgraph"
    version = __version__

    def __init__(self, tree: ast.AST, filename: str, lines: list[str]) -> None:
        # flake8 classifies plugins by their parameters: ``tree`` makes this an AST plugin;
        # ``lines`` is the text flake8 checks (the editor's buffer under ``flake8 -``).
        self.filename = filename
        self.lines = lines

    @classmethod
    def add_options(cls, parser: Any) -> None:
        register_flake8_options(parser)

    @classmethod
    def parse_options(cls, options: Any) -> None:
        """Called once per run in the main process (and in each spawned worker)."""
        global _RUN
        start_run()
        settings = Settings.from_flake8(options)
        problem = root_problem(settings.root, "--rosgraph-root", options)
        if problem is not None:
            # A user error, reported as flake8 reports a bad option value: one line, exit status 2.
            print(f"flake8: error: {problem}", file=sys.stderr)
            raise SystemExit(2)
        try:
            codes = CodeFilter.build(flake8_selectors(options), RULE_CODES)
            stdin = list(getattr(options, "filenames", None) or []) == ["-"]
            _RUN = _Run(settings, codes, selected=_ros_selected(options, codes), stdin=stdin,
                        checked=CheckedFiles.from_flake8(options), given=_given_folders(options))
        except Exception as exc:
            if settings.debug:
                raise
            _RUN = _Run(settings, CodeFilter(), error=_describe(exc))
        _install_report_hook()
        flake8_jobs.install(lambda filename: checker_results(_current_run(), filename),
                            lambda: _RUN is not None and _RUN.error is None and _RUN.selected,
                            _analyse_beside)

    def run(self) -> Iterator[tuple[int, int, str, type]]:
        try:
            run = _current_run()
        except Exception as exc:  # not even the settings could be read
            yield 1, 0, _internal_error_text(_describe(exc)), type(self)
            return
        if not run.selected:
            return  # nothing could be reported
        if flake8_jobs.deferred():
            flake8_jobs.yield_to_analysis()
            return  # the main process adds it (flake8 -jN)
        _note_buffer(run, self.filename, self.lines)
        for line, column, text in checker_results(run, self.filename):
            yield line, column, text, type(self)


def _analyse_beside(filenames: list[str]) -> bool:
    """Whether flake8 may leave the analysis to a child process while it checks the files
    (:mod:`.flake8_jobs`): a second core to run it on, ``fork``, and some report to work out
    (a warm run reads the kept ones here); not for an editor's buffer, nor under
    ``--rosgraph-debug`` (a traceback belongs to the process the user runs). Not either when a
    SARIF sidecar is wanted and the report cannot be cached: the sidecar reads the findings'
    related locations from the report in this process, which would analyse again."""
    run = _RUN
    if run is None or run.stdin or run.settings.debug or not hasattr(os, "fork") or forked.cores() < 2:
        return False
    roots: set[Path] = set()
    for filename in filenames:
        try:
            roots.add(_root_for(run, Path(os.path.abspath(filename))))
        except RootRefused:
            continue
    states = {kept_state(root, run.settings) for root in sorted(roots)}
    if run.settings.sarif and "uncacheable" in states:
        return False
    return bool(states - {"kept"})


def _given_folders(options: Any) -> tuple[Path, ...]:
    """The folders among flake8's file arguments (``.`` when none; the current folder for stdin)."""
    filenames = list(getattr(options, "filenames", None) or ["."])
    if "-" in filenames:
        return (Path.cwd(),)
    return tuple(sorted({Path(os.path.abspath(name)) for name in filenames if os.path.isdir(name)}))


def checker_results(run: _Run, filename: str) -> list[tuple[int, int, str]]:
    """What the checker reports for ``filename``: ``(line, 0-based column, "CODE text")``."""
    try:
        if run.error is not None:
            raise RuntimeError(run.error)
        findings = findings_in_file(run, filename)
        errors = analysis_errors(run, filename)
    except RootRefused as refused:  # a user's situation, not a crash: ROS000 once, with the way out
        return [(1, 0, escape_text(_analysis_error_text(str(refused))))]
    except Exception as exc:
        if run.settings.debug:
            raise
        return [(1, 0, _internal_error_text(_describe(exc)))]
    root = _root_for(run, Path(os.path.abspath(filename)))
    return ([(1, 0, escape_text(_analysis_error_text(error))) for error in errors]
            + [(f.location.line, f.location.column - 1, escape_text(f"{f.code} {localised_message(root, f)}"))
               for f in findings])


def _ros_selected(options: Any, codes: CodeFilter) -> bool:
    """Whether flake8's ``--select``/``--ignore`` (and the off-by-default opt-ins) leave any
    ROS code to report; ``--per-file-ignores`` only ever removes more. Unsure: yes."""
    try:
        from flake8.style_guide import Decision, DecisionEngine

        decider = DecisionEngine(options)
        candidates = [rule.code for rule in RULE_CODES] + [INTERNAL_ERROR_CODE]
        return any(codes(code) and decider.decision_for(code) is Decision.Selected for code in candidates)
    except Exception:
        return True


# -- the report stage ------------------------------------------------------------------------

@dataclass(frozen=True)
class _Reported:
    """A result that passed flake8's filters, as ``handle_error`` saw it."""

    code: str
    filename: str
    line: int
    column: int  # 0-based, as plugins report it
    text: str


def _install_report_hook() -> None:
    from flake8 import checker

    original = checker.Manager.report
    if getattr(original, "_rosgraph_hook", False):
        return

    @functools.wraps(original)
    def report(self: Any) -> Any:
        return _report(self, original)

    report._rosgraph_hook = True  # type: ignore[attr-defined]
    checker.Manager.report = report


def _report(manager: Any, original: Callable[[Any], Any]) -> Any:
    run = _RUN
    if run is None:
        return original(manager)
    reported: list[_Reported] = []
    internal_errors: set[str] = set()
    guide = manager.style_guide
    inner = guide.handle_error
    shadowed = vars(guide).get("handle_error")

    def handle_error(code: str, filename: str, line_number: int, column_number: int | None,
                     text: str, physical_line: str | None = None) -> int:
        if code == INTERNAL_ERROR_CODE and text in internal_errors:
            return 0
        count = inner(code=code, filename=filename, line_number=line_number, column_number=column_number,
                      text=text, physical_line=physical_line)
        if count:
            if code == INTERNAL_ERROR_CODE:
                internal_errors.add(text)
            reported.append(_Reported(code, filename, line_number, column_number or 0, text))
        return count

    guide.handle_error = handle_error
    try:
        counts = original(manager)
    finally:
        if shadowed is None:
            del guide.handle_error
        else:
            guide.handle_error = shadowed
    if run.settings.sarif is not None:
        try:
            _write_sidecar(run, reported, _plugin_origins(manager))
        except Exception as exc:
            if run.settings.debug:
                raise
            print(f"flake8-rosgraph: error: could not write the SARIF file {run.settings.sarif}: "
                  f"{_describe(exc)}", file=sys.stderr)
            # Counted as one more reported result, so that flake8 exits with an error status.
            total, found = counts
            return total + 1, found + 1
    return counts


def _matching_finding(run: _Run, item: _Reported) -> tuple[Path, Finding] | None:
    """The workspace finding behind a reported ROS result, for its related locations."""
    path = Path(os.path.abspath(item.filename))
    root = _root_for(run, path)
    for finding in findings_in_file(run, item.filename):
        same_place = (finding.location.line, finding.location.column - 1) == (item.line, item.column)
        if same_place and (finding.code, escape_text(localised_message(root, finding))) == (item.code, item.text):
            return root, finding
    return None


def _write_sidecar(run: _Run, reported: list[_Reported], origins: dict[str, Any]) -> None:
    from . import sarif

    problems = []
    for item in reported:
        match = None
        if item.code.startswith("ROS") and item.code != INTERNAL_ERROR_CODE:
            match = _matching_finding(run, item)
        if match is not None:
            problems.append(sarif.finding_problem(*match))
        else:
            place = sarif.Place(Path(os.path.abspath(item.filename)), item.line, item.column + 1)
            problems.append(sarif.Problem(place, item.code, item.text))
    cwd = Path.cwd()
    log = sarif.sarif_log(
        problems, sarif.catalogue(), srcroot=find_vcs_root(cwd) or cwd, category=SIDECAR_CATEGORY,
        origins={prefix: sarif.Origin(*origin) for prefix, origin in origins.items()},
        successful=not any(item.code == INTERNAL_ERROR_CODE for item in reported),
    )
    sarif.write(run.settings.sarif, log)


def _plugin_origins(manager: Any) -> dict[str, tuple[str, str]]:
    """Code prefix → (plugin, version), from flake8 ≥ 5's ``manager.plugins`` or flake8 4's ``manager.checks``."""
    origins: dict[str, tuple[str, str]] = {}
    try:
        plugins = getattr(manager, "plugins", None)
        if plugins is not None and hasattr(plugins, "tree"):
            for loaded in itertools.chain(plugins.tree, plugins.logical_line, plugins.physical_line):
                origins[loaded.entry_name] = (loaded.plugin.package, loaded.plugin.version)
        else:
            for plugin in manager.checks.plugins.values():
                if plugin.name.startswith("pycodestyle."):  # flake8 4 registers pycodestyle per check
                    origins["E"] = origins["W"] = (plugin.plugin_name, plugin.version)
                else:
                    origins[plugin.name] = (plugin.plugin_name, plugin.version)
    except Exception:  # what is known of other plugins is a nicety, never worth a failure
        return {}
    return {prefix: origin for prefix, origin in sorted(origins.items()) if _CODE_PREFIX.match(prefix)}
