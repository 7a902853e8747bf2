"""``flake8 --rosgraph-sarif FILE``: the terminal output stays, the sidecar holds what flake8 reported."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from .conftest import parse_flake8, validate_sarif
from .test_plugin_flake8 import flake8_in_process

STYLE = """\
import os
x = 1  # this line is long enough to be reported as E501 by pycodestyle, which it is
y = 2  # this line is long enough to be reported as E501 too, but it is silenced  # noqa: E501
"""


@pytest.fixture
def mixed(workspace: Path) -> Path:
    (workspace / "src/pkg_b/pkg_b/style.py").write_text(STYLE)
    return workspace


@pytest.fixture
def run(monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]):
    return lambda args, cwd: flake8_in_process(["--isolated", "--max-line-length", "79", *args],
                                               cwd, monkeypatch, capsys)


def _rows(log: dict) -> list[tuple[str, int, int, str]]:
    return sorted((r["locations"][0]["physicalLocation"]["artifactLocation"]["uri"],
                   r["locations"][0]["physicalLocation"]["region"]["startLine"],
                   r["locations"][0]["physicalLocation"]["region"]["startColumn"], r["ruleId"])
                  for run in log["runs"] for r in run["results"])


@pytest.mark.parametrize("extra", [[], ["--extend-ignore", "F401"], ["--format", "pylint"], ["--show-source"]])
def test_terminal_output_is_unchanged_and_sidecar_matches_it(fake_engine: Path, mixed: Path, run,
                                                             extra: list[str]) -> None:
    plain_status, plain = run([*extra, "."], mixed)
    status, out = run([*extra, "--rosgraph-sarif", "results.sarif", "."], mixed)
    assert (status, out) == (plain_status, plain)
    log = json.loads((mixed / "results.sarif").read_text())
    validate_sarif(log)
    reported = {(r[0], r[1], r[3]) for r in _rows(log)}
    assert ("src/pkg_b/pkg_b/style.py", 3, "E501") not in reported      # noqa'd
    assert ("src/pkg_b/pkg_b/listener.py", 6, "ROS003") not in reported  # noqa'd
    assert ("src/pkg_b/pkg_b/style.py", 1, "F401") in reported or "F401" in extra
    if "--format" not in extra and "--show-source" not in extra:
        assert _rows(log) == parse_flake8(out)


def test_ros_results_carry_rule_metadata_and_related_locations(fake_engine: Path, mixed: Path, run) -> None:
    run(["--rosgraph-sarif", "results.sarif", "."], mixed)
    log = json.loads((mixed / "results.sarif").read_text())
    ours, *others = log["runs"]
    rules = ours["tool"]["driver"]["rules"]
    (loop,) = [r for r in ours["results"] if r["ruleId"] == "ROS002"]
    assert rules[loop["ruleIndex"]]["id"] == "ROS002"
    assert rules[loop["ruleIndex"]]["help"]["markdown"].startswith("## What it does")
    assert "[publisher '/loop'](1)" in loop["message"]["text"]
    assert loop["relatedLocations"][0]["physicalLocation"]["region"]["startLine"] == 8
    assert not any(r["id"][:3] != "ROS" for r in rules)  # only our rules under our driver
    by_tool = {run["tool"]["driver"]["name"]: run for run in others}
    (e501,) = [r for r in by_tool["pycodestyle"]["tool"]["driver"]["rules"] if r["id"] == "E501"]
    (f401,) = [r for r in by_tool["pyflakes"]["tool"]["driver"]["rules"] if r["id"] == "F401"]
    assert "pycodestyle" in e501["properties"]["tags"]
    assert "pyflakes" in f401["properties"]["tags"]
    assert ours["automationDetails"]["id"] == "flake8-rosgraph/flake8/"
    assert by_tool["pyflakes"]["automationDetails"]["id"] == "flake8-rosgraph/flake8/pyflakes/"


def test_sidecar_path_from_the_environment(fake_engine: Path, mixed: Path, run,
                                           monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("ROSGRAPH_SARIF", str(mixed / "env.sarif"))
    run(["--select", "ROS", "."], mixed)
    assert {r[3] for r in _rows(json.loads((mixed / "env.sarif").read_text()))} == {"ROS001", "ROS002", "ROS003"}


def test_unwritable_sidecar_is_a_warning_not_a_crash(fake_engine: Path, mixed: Path, run) -> None:
    (mixed / "blocker").write_text("")
    plain = run(["--select", "ROS", "."], mixed)
    with_sidecar = run(["--select", "ROS", "--rosgraph-sarif", "blocker/x.sarif", "."], mixed)
    assert with_sidecar == plain


def test_no_sidecar_without_the_option(fake_engine: Path, mixed: Path, run) -> None:
    run(["."], mixed)
    assert not list(mixed.glob("*.sarif"))
