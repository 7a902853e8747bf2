"""The SARIF writer on its own: schema, GitHub's fields, fingerprints, determinism."""
from __future__ import annotations

import json
import random
import shutil
from pathlib import Path

from flake8_rosgraph import __version__
from flake8_rosgraph.graph.model import Diagnostic, Location
from flake8_rosgraph.rules import RULES
from flake8_rosgraph.rules.base import Finding
from flake8_rosgraph.sarif import FINGERPRINT_KEY, Origin, Place, Problem, catalogue, dumps, finding_problem, sarif_log

from .conftest import validate_sarif

SOURCE = ("import rclpy\n\n\nnode.create_publisher(String, 'cmd_vel', 10)\n"
          "name = 'ß'; node.create_subscription(String, 'cmdvel', cb, 10)\n")


def _workspace(root: Path) -> Path:
    (root / "pkg").mkdir(parents=True)
    (root / "pkg" / "a b.py").write_text(SOURCE, encoding="utf-8")
    return root


def _findings() -> list[Finding]:
    sub = Location("pkg/a b.py", 5, 13)
    return [
        Finding(Location("pkg/a b.py", 4, 1), "ROS001",
                "topic '/cmd_vel' has no subscriber; did you mean '/cmdvel' (subscribed at pkg/a b.py:5)?",
                ((sub, "subscription '/cmdvel' [near miss]"),)),
        Finding(sub, "ROS003", "topic '/cmdvel' has no publisher"),
    ]


def _log(root: Path, findings: list[Finding] | None = None, **kwargs) -> dict:
    problems = [finding_problem(root, f) for f in (findings or _findings())]
    return sarif_log(problems, catalogue(), srcroot=root, category="test", **kwargs)


def test_log_is_valid_sarif_with_what_github_reads(tmp_path: Path) -> None:
    root = _workspace(tmp_path / "ws")
    log = _log(root, diagnostics=[(root, Diagnostic("pkg/a b.py", 2, "budget exhausted"))])
    validate_sarif(log)
    run = log["runs"][0]
    driver = run["tool"]["driver"]
    assert (driver["name"], driver["semanticVersion"]) == ("flake8-rosgraph", __version__)
    assert driver["informationUri"].startswith("https://")
    assert [r["id"] for r in driver["rules"]] == ["ROS000"] + [rule.code for rule in RULES]
    for rule in driver["rules"]:
        assert rule["shortDescription"]["text"] and rule["fullDescription"]["text"]
        assert rule["help"]["text"] and rule["help"]["markdown"]
        assert rule["defaultConfiguration"]["level"] in {"error", "warning", "note"}
        assert {"tags", "precision", "problem.severity"} <= set(rule["properties"])
    (ros010,) = [r for r in driver["rules"] if r["id"] == "ROS010"]
    assert ros010["defaultConfiguration"] == {"enabled": False, "level": "note"}
    assert run["automationDetails"]["id"] == "test/"
    assert run["columnKind"] == "unicodeCodePoints"
    assert run["invocations"][0]["toolExecutionNotifications"][0]["message"]["text"] == "budget exhausted"
    assert run["invocations"][0]["executionSuccessful"] is True
    for rule in driver["rules"]:
        assert rule["helpUri"].startswith(driver["informationUri"])
    ros003 = next(r for r in driver["rules"] if r["id"] == "ROS003")
    assert ros003["helpUri"].endswith("docs/rules.md#ros003-subscription-without-publisher")
    failed = _log(root, successful=False)
    assert failed["runs"][0]["invocations"][0]["executionSuccessful"] is False


def test_results_link_related_locations_with_relative_uris(tmp_path: Path) -> None:
    root = _workspace(tmp_path / "ws")
    first, second = _log(root)["runs"][0]["results"]
    assert (first["ruleId"], first["ruleIndex"], first["level"]) == ("ROS001", 1, "warning")
    assert first["message"]["text"].endswith("Related: [subscription '/cmdvel' \\[near miss\\]](1).")
    assert first["relatedLocations"][0]["id"] == 1
    location = first["locations"][0]["physicalLocation"]
    assert location["artifactLocation"] == {"uri": "pkg/a%20b.py", "uriBaseId": "%SRCROOT%"}
    assert location["region"] == {"startLine": 4, "startColumn": 1, "endLine": 4, "endColumn": 45}
    prints = first["partialFingerprints"]
    assert set(prints) == {FINGERPRINT_KEY, "primaryLocationLineHash"}
    assert prints["primaryLocationLineHash"].endswith(":1")
    # a character column, as given (the line holds a non-ASCII character before it)
    assert second["locations"][0]["physicalLocation"]["region"]["startColumn"] == 13


def test_files_outside_the_source_root_get_absolute_uris(tmp_path: Path) -> None:
    root = _workspace(tmp_path / "ws")
    log = sarif_log([Problem(Place(tmp_path / "other.py", 1, 1), "E501", "line too long")], catalogue(),
                    srcroot=root, category="test", origins={"E": Origin("pycodestyle", "2.11.0")})
    validate_sarif(log)
    ours, theirs = log["runs"]
    assert ours["results"] == [] and ours["tool"]["driver"]["name"] == "flake8-rosgraph"
    (result,) = theirs["results"]
    assert result["locations"][0]["physicalLocation"]["artifactLocation"] == {
        "uri": (tmp_path / "other.py").as_uri()}
    # another plugin's code is reported under that plugin, never under our driver
    assert (theirs["tool"]["driver"]["name"], theirs["tool"]["driver"]["version"]) == ("pycodestyle", "2.11.0")
    assert theirs["automationDetails"]["id"] == "test/pycodestyle/"
    rule = theirs["tool"]["driver"]["rules"][result["ruleIndex"]]
    assert rule["id"] == "E501" and "pycodestyle" in rule["properties"]["tags"]


def _fingerprints(log: dict) -> list[str]:
    return [r["partialFingerprints"][FINGERPRINT_KEY] for run in log["runs"] for r in run["results"]]


def test_fingerprints_do_not_depend_on_machine_or_line_numbers(tmp_path: Path) -> None:
    here = _workspace(tmp_path / "here")
    there = tmp_path / "elsewhere" / "checkout"
    shutil.copytree(here, there)
    assert _fingerprints(_log(here)) == _fingerprints(_log(there))
    moved = [Finding(Location(f.location.path, f.location.line + 2, f.location.column), f.code,
                     f.message.replace(":5", ":7"),
                     tuple((Location(loc.path, loc.line + 2, loc.column), label) for loc, label in f.related))
             for f in _findings()]
    (there / "pkg" / "a b.py").write_text("# header\n\n" + SOURCE, encoding="utf-8")
    assert _fingerprints(_log(there, moved)) == _fingerprints(_log(here))
    renamed = [Finding(f.location, f.code, f.message.replace("cmd_vel", "cmd_vel2")) for f in _findings()]
    assert _fingerprints(_log(here, renamed))[0] != _fingerprints(_log(here))[0]


def test_identical_problems_get_distinct_fingerprints(tmp_path: Path) -> None:
    root = _workspace(tmp_path / "ws")
    twice = [Problem(Place(root / "pkg" / "a b.py", 2, 1), "W391", "blank line at end of file"),
             Problem(Place(root / "pkg" / "a b.py", 3, 1), "W391", "blank line at end of file")]
    prints = _fingerprints(sarif_log(twice, catalogue(), srcroot=root, category="test"))
    assert len(set(prints)) == 2


def test_output_is_deterministic(tmp_path: Path) -> None:
    root = _workspace(tmp_path / "ws")
    problems = [finding_problem(root, f) for f in _findings()] + [
        Problem(Place(root / "pkg" / "a b.py", 1, 1), "F401", "'rclpy' imported but unused")]
    shuffled = problems[:]
    random.Random(7).shuffle(shuffled)
    texts = {dumps(sarif_log(p, catalogue(), srcroot=root, category="test")) for p in (problems, shuffled)}
    assert len(texts) == 1
    assert json.loads(texts.pop())["version"] == "2.1.0"


def test_serialisation_is_byte_identical_to_jschema_to_python(tmp_path: Path, monkeypatch) -> None:
    """The log of the example workspace — every rule's descriptor, findings with related
    locations, foreign codes, tool notifications — written by :func:`sarif.plain` and by
    the reference serialiser ``jschema_to_python.to_json`` it replaces: the same bytes."""
    import jschema_to_python.to_json as reference

    from flake8_rosgraph import sarif
    from flake8_rosgraph.cache import build_report
    from flake8_rosgraph.options import Settings

    root = Path(__file__).resolve().parents[2] / "examples"
    report = build_report(root, Settings.resolve({}, {}))
    assert report.findings, "the example workspace has findings to write"
    problems = [finding_problem(root, f) for f in report.findings] + [
        Problem(Place(root / "src" / "x.py", 3, 1), "F401", "'os' imported but unused"),
        Problem(Place(root / "src" / "x.py", 4, 80), "E501", "line too long (88 > 79 characters)")]
    origins = {"F": Origin("pyflakes", "3.2.0"), "E": Origin("pycodestyle", "2.12.1")}
    diagnostics = [(root, d) for d in report.diagnostics] + [
        (root, Diagnostic("src/y.py", 2, "syntax error: invalid syntax", "warning"))]

    def log() -> str:
        return dumps(sarif_log(problems, catalogue(), srcroot=root, category="examples",
                               origins=origins, diagnostics=diagnostics))

    ours = log()
    monkeypatch.setattr(sarif, "plain", lambda obj: json.loads(reference.to_json(obj)))
    assert ours == log()
