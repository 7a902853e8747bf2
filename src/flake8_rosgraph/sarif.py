"""SARIF 2.1.0 output, shaped for GitHub code scanning.

Both front ends produce the same log: ``flake8 --rosgraph-sarif FILE`` (every
code flake8 reported after its filters) and ``flake8-rosgraph check --sarif
FILE`` (the ROS codes). What GitHub reads is always there: the driver's name,
``semanticVersion`` and ``informationUri``; for each rule ``shortDescription``,
``fullDescription``, ``help`` (text and markdown, from the rule's ruff-style
docstring), ``defaultConfiguration.level`` and ``properties`` (``tags``,
``precision``, ``problem.severity``); for each result ``ruleId``, ``ruleIndex``,
``level``, a message that links its ``relatedLocations`` (``[label](1)``), a
region with 1-based character columns (``columnKind: unicodeCodePoints``),
repository-relative URIs under ``%SRCROOT%`` and ``partialFingerprints`` that
depend on no absolute path and no line number; ``automationDetails.id`` names
the category. Codes of other flake8 plugins get a rule entry with what is known
of them (the plugin's name and version).

This is the only module that imports ``sarif_om``. The object model is turned
into JSON by :func:`plain`, which writes what ``jschema_to_python.to_json``
writes, in the same order, without its deep copy of every object at every
level and its JSON round trip (most of the sidecar's cost before).
"""
from __future__ import annotations

import inspect
import json
import os
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Any, Iterable, Mapping, Sequence
from urllib.parse import quote

import attr
import sarif_om as om

from .escaping import escape_text, json_safe
from . import __version__
from .graph.model import Diagnostic
from .options import INTERNAL_ERROR_CODE
from .findings import Finding
from .fingerprints import Ranks, SourceLines, finding_fingerprint, line_hash, without_line_numbers

TOOL_NAME = "flake8-rosgraph"
INFORMATION_URI = "https://github.com/flake8-rosgraph/flake8-rosgraph"
#: Each rule's section of the rules page (the anchor GitHub gives the ``## CODE name`` heading).
RULES_URI = INFORMATION_URI + "/blob/main/docs/rules.md"
SCHEMA_URI = "https://json.schemastore.org/sarif-2.1.0.json"
SRCROOT = "%SRCROOT%"
FINGERPRINT_KEY = "rosgraphFinding/v1"

#: GitHub's ``problem.severity`` for each SARIF level.
_SEVERITY = {"error": "error", "warning": "warning", "note": "recommendation"}
#: Precision when a rule does not declare one: the louder the level, the surer the rule must be.
_PRECISION = {"error": "high", "warning": "medium", "note": "low"}


@dataclass(frozen=True, order=True)
class Place:
    """A position in a file: absolute path, 1-based line and 1-based character column."""

    path: Path
    line: int
    column: int


@dataclass(frozen=True, order=True)
class Problem:
    """One reported problem, whichever tool found it; ``related`` holds (place, label) pairs."""

    place: Place
    code: str
    message: str
    related: tuple[tuple[Place, str], ...] = ()


def finding_problem(root: Path, finding: Finding) -> Problem:
    """A rule finding (root-relative locations) as a :class:`Problem` (absolute paths)."""

    def place(location: Any) -> Place:
        return Place(Path(root, location.path), location.line, location.column)

    related = tuple((place(location), label) for location, label in finding.related)
    return Problem(place(finding.location), finding.code, finding.message, related)


@dataclass(frozen=True)
class Origin:
    """The flake8 plugin behind a code that is not ours."""

    name: str
    version: str


@dataclass(frozen=True)
class RuleInfo:
    """What a SARIF rule entry says; built from a ``Rule`` or from what is known of a foreign code."""

    code: str
    name: str
    level: str
    summary: str
    doc: str
    enabled: bool = True
    precision: str | None = None
    tags: tuple[str, ...] = ()
    help_uri: str | None = None


def rule_info(rule: Any) -> RuleInfo:
    """The SARIF view of a :class:`~flake8_rosgraph.rules.base.Rule` instance."""
    family = {"0": "graph-wiring", "1": "rclpy-misuse", "2": "launch"}.get(rule.code[3:4], "ros")
    return RuleInfo(
        code=rule.code, name=rule.name, level=rule.level, summary=rule.summary,
        doc=inspect.cleandoc(type(rule).__doc__ or rule.summary),
        enabled=bool(rule.default_enabled), precision=getattr(rule, "precision", None),
        tags=("ros2", family), help_uri=f"{RULES_URI}#{rule.code.lower()}-{rule.name}",
    )


INTERNAL_ERROR_RULE = RuleInfo(
    code=INTERNAL_ERROR_CODE, name="internal-error", level="error",
    summary="flake8-rosgraph failed; the graph rules did not run",
    doc=("## What it does\nReports that flake8-rosgraph itself failed, instead of crashing flake8.\n\n"
         "## Why is this bad?\nThe ROS graph rules did not run, so their silence proves nothing.\n\n"
         "## Use instead\nRun again with `--rosgraph-debug` (or `ROSGRAPH_DEBUG=1`) to see the "
         "traceback, and report it."),
    precision="high", tags=("ros2", "tool"), help_uri=INFORMATION_URI + "#reliability",
)


def catalogue() -> list[RuleInfo]:
    """Every ROS rule, in code order, with the internal-error pseudo-rule first."""
    from .rules import RULES

    return [INTERNAL_ERROR_RULE, *(rule_info(rule) for rule in RULES)]


def foreign_rule(code: str, origin: Origin | None) -> RuleInfo:
    """What is known of another plugin's code: its plugin, if flake8 told us."""
    source = f"{origin.name} {origin.version}" if origin else "a flake8 plugin"
    return RuleInfo(
        code=code, name=code, level="warning", summary=f"{code}, reported by {source} through flake8",
        doc=f"`{code}` is reported by {source}; see that plugin's documentation.",
        tags=("flake8",) + ((origin.name,) if origin else ()),
    )


def _sections(doc: str) -> dict[str, str]:
    sections: dict[str, str] = {}
    current = ""
    for line in doc.splitlines():
        if line.startswith("## "):
            current = line[3:].strip()
            sections[current] = ""
        else:
            sections[current] = sections.get(current, "") + line + "\n"
    return {name: text.strip() for name, text in sections.items()}


def _plain(markdown: str) -> str:
    """Markdown to readable plain text: headings lose their ``#``, fences disappear."""
    lines = [line[3:] if line.startswith("## ") else line
             for line in markdown.splitlines() if not line.startswith("```")]
    return "\n".join(lines).strip()


def _escape(text: str) -> str:
    """SARIF message text: literal brackets must be escaped, or they read as links."""
    return text.replace("\\", "\\\\").replace("[", "\\[").replace("]", "\\]")


def _descriptor(info: RuleInfo) -> om.ReportingDescriptor:
    what = _sections(info.doc).get("What it does") or info.summary
    properties = om.PropertyBag(tags=list(info.tags))
    setattr(properties, "precision", info.precision or _PRECISION[info.level])
    setattr(properties, "problem.severity", _SEVERITY[info.level])
    return om.ReportingDescriptor(
        id=info.code,
        name=info.name,
        short_description=om.MultiformatMessageString(text=info.summary[:1].upper() + info.summary[1:]),
        full_description=om.MultiformatMessageString(text=" ".join(what.split())),
        help=om.MultiformatMessageString(text=_plain(info.doc), markdown=info.doc),
        help_uri=info.help_uri,
        default_configuration=om.ReportingConfiguration(level=info.level, enabled=info.enabled),
        properties=properties,
    )


class _Artifacts:
    """URIs relative to the source root, and the stripped text of source lines for fingerprints."""

    def __init__(self, srcroot: Path) -> None:
        self.srcroot = Path(os.path.abspath(srcroot))
        self._lines = SourceLines()
        self._uris: dict[Path, tuple[str, str | None]] = {}

    def location(self, path: Path) -> om.ArtifactLocation:
        uri, base = self._uri_and_base(path)
        return om.ArtifactLocation(uri=uri) if base is None else om.ArtifactLocation(uri=uri, uri_base_id=base)

    def uri(self, path: Path) -> str:
        return self._uri_and_base(path)[0]

    def _uri_and_base(self, path: Path) -> tuple[str, str | None]:
        """Worked out once per file: a log names each file many times."""
        known = self._uris.get(path)
        if known is None:
            absolute = Path(os.path.abspath(path))
            try:
                known = (quote(absolute.relative_to(self.srcroot).as_posix()), SRCROOT)
            except ValueError:
                known = (absolute.as_uri(), None)
            self._uris[path] = known
        return known

    def line_text(self, place: Place) -> str:
        return self._lines.text(place.path, place.line)

    def line_end(self, place: Place) -> int:
        """The 1-based character column just past the line's last non-blank character."""
        return len(self._lines.raw(place.path, place.line).rstrip()) + 1


def _physical(artifacts: _Artifacts, place: Place) -> om.PhysicalLocation:
    """The place, its region reaching to the end of the source line (GitHub underlines the region)."""
    start = max(place.column, 1)
    end = max(start + 1, artifacts.line_end(place))
    return om.PhysicalLocation(
        artifact_location=artifacts.location(place.path),
        region=om.Region(start_line=max(place.line, 1), start_column=start,
                         end_line=max(place.line, 1), end_column=end),
    )


def _fingerprints(artifacts: _Artifacts, problem: Problem, ranks: Ranks) -> dict[str, str]:
    """Stable across runs and machines: no absolute path, no line number, only what the problem is."""
    line = artifacts.line_text(problem.place)
    uri = artifacts.uri(problem.place.path)
    rank = ranks.next((problem.code, uri, without_line_numbers(problem.message), line))
    related = [(artifacts.uri(place.path), label) for place, label in problem.related]
    return {FINGERPRINT_KEY: finding_fingerprint(problem.code, uri, problem.message, line, rank, related),
            "primaryLocationLineHash": line_hash(line, rank)}


def _message(problem: Problem) -> om.Message:
    text = _escape(escape_text(problem.message))
    if problem.related:
        links = ", ".join(f"[{_escape(escape_text(label))}]({index})"
                          for index, (_, label) in enumerate(problem.related, 1))
        text += f" Related: {links}."
    return om.Message(text=text)


def _notification(artifacts: _Artifacts, root: Path, diagnostic: Diagnostic) -> om.Notification:
    place = Place(root / diagnostic.path, diagnostic.line, 1)
    level = diagnostic.severity if diagnostic.severity in _SEVERITY else "warning"
    return om.Notification(message=om.Message(text=escape_text(diagnostic.message)), level=level,
                           locations=[om.Location(physical_location=_physical(artifacts, place))])


def _results(artifacts: _Artifacts, problems: list[Problem], infos: list[RuleInfo]) -> list[om.Result]:
    index = {info.code: i for i, info in enumerate(infos)}
    ranks = Ranks()
    results = []
    for problem in problems:
        related = [
            om.Location(id=i, physical_location=_physical(artifacts, place), message=om.Message(text=label))
            for i, (place, label) in enumerate(problem.related, 1)
        ]
        results.append(om.Result(
            rule_id=problem.code, rule_index=index[problem.code], level=infos[index[problem.code]].level,
            message=_message(problem),
            locations=[om.Location(physical_location=_physical(artifacts, problem.place))],
            related_locations=related or None,
            partial_fingerprints=_fingerprints(artifacts, problem, ranks),
        ))
    return results


def _run(driver: om.ToolComponent, infos: list[RuleInfo], problems: list[Problem], artifacts: _Artifacts,
         category: str, invocation: om.Invocation) -> om.Run:
    driver.rules = [_descriptor(info) for info in infos]
    return om.Run(
        tool=om.Tool(driver=driver),
        automation_details=om.RunAutomationDetails(id=f"{category}/"),
        column_kind="unicodeCodePoints",
        original_uri_base_ids={SRCROOT: om.ArtifactLocation(uri=artifacts.srcroot.as_uri() + "/")},
        invocations=[invocation],
        results=_results(artifacts, problems, infos),
    )


def sarif_log(
    problems: Iterable[Problem],
    rules: Sequence[RuleInfo],
    *,
    srcroot: Path,
    category: str,
    origins: Mapping[str, Origin] | None = None,
    diagnostics: Iterable[tuple[Path, Diagnostic]] = (),
    successful: bool = True,
) -> dict[str, Any]:
    """The SARIF log (as JSON-ready data) of ``problems``.

    The first run is ours: its driver describes ``rules`` (every ROS rule,
    whether it fired or not) and holds their results. Codes outside ``rules``
    (other flake8 plugins, through the sidecar) go to one run per plugin,
    found by code prefix in ``origins``, whose driver is that plugin — so code
    scanning never shows another tool's finding as ours. ``diagnostics``
    (workspace root, analysis gap) become our run's tool execution
    notifications; ``successful`` is false only when the tool itself failed.
    """
    origins = origins or {}
    problems = sorted(set(problems))
    artifacts = _Artifacts(srcroot)
    ours = list(rules)
    known = {info.code for info in ours}
    notifications = [_notification(artifacts, root, d) for root, d in
                     sorted(set(diagnostics), key=lambda rd: (str(rd[0]), rd[1]))]
    runs = [_run(om.ToolComponent(name=TOOL_NAME, semantic_version=__version__, version=__version__,
                                  information_uri=INFORMATION_URI),
                 ours, [p for p in problems if p.code in known], artifacts, category,
                 om.Invocation(execution_successful=successful, tool_execution_notifications=notifications or None))]
    by_tool: dict[Origin | None, list[Problem]] = {}
    for problem in problems:
        if problem.code not in known:
            by_tool.setdefault(_origin_for(problem.code, origins), []).append(problem)
    for origin, tool_problems in sorted(by_tool.items(), key=lambda item: (item[0] is not None, item[0].name if item[0] else "")):
        infos = [foreign_rule(code, origin) for code in sorted({p.code for p in tool_problems})]
        name = origin.name if origin else "flake8"
        driver = om.ToolComponent(name=name, version=origin.version if origin else None)
        runs.append(_run(driver, infos, tool_problems, artifacts, f"{category}/{name}",
                         om.Invocation(execution_successful=True)))
    log = plain(om.SarifLog(version="2.1.0", schema_uri=SCHEMA_URI, runs=runs))
    # to_json drops values equal to the schema default ("warning"), but GitHub
    # reads levels literally: put them back.
    for run, data in zip(runs, log["runs"]):
        for descriptor, rule in zip(data["tool"]["driver"]["rules"], run.tool.driver.rules):
            descriptor["defaultConfiguration"]["level"] = rule.default_configuration.level
        for result, original in zip(data.get("results", []), run.results):
            result["level"] = original.level
    return log


def plain(obj: Any) -> Any:
    """``obj`` (a ``sarif_om`` object, or lists, dicts and scalars of them) as JSON data.

    The rules of ``jschema_to_python``: an attribute equal to its declared default
    is left out, attributes with a schema name are written under it — after the
    others, as that library re-inserts them — and anything JSON cannot hold is
    written as ``str()``.
    """
    if isinstance(obj, (str, int, float, bool)) or obj is None:
        return obj
    if isinstance(obj, (list, tuple)):
        return [plain(item) for item in obj]
    if isinstance(obj, dict):
        return {key: plain(value) for key, value in obj.items()}
    if not attr.has(type(obj)):
        return str(obj)
    fields = _fields(type(obj))
    out: dict[str, Any] = {}
    renamed: list[tuple[str, Any]] = []
    for name, value in vars(obj).items():
        field = fields.get(name)
        if field is not None and value == _default(field):
            continue
        schema_name = field.metadata.get("schema_property_name") if field is not None else None
        if schema_name and schema_name != name:
            renamed.append((name, value))
        else:
            out[name] = plain(value)
    order = list(fields)
    for name, value in sorted(renamed, key=lambda item: order.index(item[0])):
        out[fields[name].metadata["schema_property_name"]] = plain(value)
    return out


@lru_cache(maxsize=None)
def _fields(cls: type) -> dict[str, Any]:
    return {field.name: field for field in attr.fields(cls)}


def _default(field: Any) -> Any:
    default = field.default
    return default.factory() if isinstance(default, attr.Factory) else default  # type: ignore[arg-type]


def _origin_for(code: str, origins: Mapping[str, Origin]) -> Origin | None:
    prefixes = [prefix for prefix in origins if code.startswith(prefix)]
    return origins[max(prefixes, key=len)] if prefixes else None


def dumps(log: Mapping[str, Any]) -> str:
    """The log as deterministic JSON text."""
    return json_safe(json.dumps(log, indent=2, ensure_ascii=False)) + "\n"


def write(path: Path, log: Mapping[str, Any]) -> None:
    """Write the log to ``path`` (parent directories created)."""
    path = Path(path)
    if path.parent != Path():
        path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(dumps(log), encoding="utf-8")
