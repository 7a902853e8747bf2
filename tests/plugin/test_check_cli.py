"""``flake8-rosgraph check``: the same findings as the plugin, without flake8."""
from __future__ import annotations

import argparse
import json
from pathlib import Path

import pytest

from flake8_rosgraph import check_cli

from .conftest import EXPECTED_STANDARD, parse_flake8, validate_sarif
from .test_plugin_flake8 import flake8_in_process


def check(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(prog="flake8-rosgraph")
    check_cli.add_parser(parser.add_subparsers(dest="command"))
    args = parser.parse_args(["check", *argv])
    return args.run(args)


@pytest.fixture
def in_ws(workspace: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    monkeypatch.chdir(workspace)
    return workspace


def test_findings_and_exit_status_match_flake8(fake_engine: Path, in_ws: Path, monkeypatch: pytest.MonkeyPatch,
                                               capsys: pytest.CaptureFixture[str]) -> None:
    assert check(["."]) == check_cli.EXIT_FINDINGS
    out = capsys.readouterr().out
    assert parse_flake8(out) == EXPECTED_STANDARD
    _, flake8_out = flake8_in_process(["--isolated", "--select", "ROS", "."], in_ws, monkeypatch, capsys)
    assert sorted(line.removeprefix("./") for line in flake8_out.splitlines()) == sorted(out.splitlines())


def test_a_file_path_reports_that_file_only(fake_engine: Path, in_ws: Path,
                                            capsys: pytest.CaptureFixture[str]) -> None:
    assert check(["src/pkg_b/pkg_b/listener.py"]) == 1
    assert parse_flake8(capsys.readouterr().out) == [("src/pkg_b/pkg_b/listener.py", 7, 10, "ROS003")]


def test_clean_workspace_exits_zero(fake_engine: Path, in_ws: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert check(["--external-topics", "/orphan,/nobody", "--ignore", "ROS002", "."]) == check_cli.EXIT_CLEAN
    assert capsys.readouterr().out == ""


def test_selection_and_off_by_default_rules(fake_engine: Path, in_ws: Path,
                                            capsys: pytest.CaptureFixture[str]) -> None:
    (in_ws / "src/pkg_a/pkg_a/extra.py").write_text("node.create_subscription(String, topic, cb, 10)\n")
    check(["--select", "ROS", "."])
    assert "ROS010" not in capsys.readouterr().out
    check(["--extend-select", "ROS010", "."])
    assert [row[3] for row in parse_flake8(capsys.readouterr().out)] == ["ROS010", "ROS002", "ROS003"]


def test_json_format(fake_engine: Path, in_ws: Path, capsys: pytest.CaptureFixture[str]) -> None:
    check(["--format", "json", "."])
    data = json.loads(capsys.readouterr().out)
    assert [(f["path"], f["line"], f["column"], f["code"]) for f in data["findings"]] == EXPECTED_STANDARD
    (loop,) = [f for f in data["findings"] if f["code"] == "ROS002"]
    assert loop["related"] == [{"path": "src/pkg_a/pkg_a/talker.py", "line": 8, "column": 10,
                                "label": "publisher '/loop'"}]


def test_sarif_uses_the_repository_root(fake_engine: Path, in_ws: Path, tmp_path: Path,
                                        capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / ".git").mkdir()  # the workspace sits inside a repository
    check(["--sarif", str(tmp_path / "out.sarif"), "."])
    assert parse_flake8(capsys.readouterr().out) == EXPECTED_STANDARD  # terminal output unchanged
    log = json.loads((tmp_path / "out.sarif").read_text())
    validate_sarif(log)
    uris = [r["locations"][0]["physicalLocation"]["artifactLocation"]["uri"] for r in log["runs"][0]["results"]]
    assert uris == ["ws/" + path for path, *_ in EXPECTED_STANDARD]
    assert log["runs"][0]["automationDetails"]["id"] == "flake8-rosgraph/check/"


def test_usage_and_internal_errors_exit_two(fake_engine: Path, in_ws: Path,
                                            capsys: pytest.CaptureFixture[str]) -> None:
    assert check(["does-not-exist"]) == check_cli.EXIT_ERROR
    (in_ws / "src/pkg_a/pkg_a/broken.py").write_text("# FAKE_CRASH\n")
    assert check(["."]) == check_cli.EXIT_ERROR
    assert "fake analysis crashed" in capsys.readouterr().err
    with pytest.raises(RuntimeError, match="fake analysis crashed"):
        check(["--debug", "."])
    with pytest.raises(SystemExit) as usage:
        check(["--format", "xml", "."])
    assert usage.value.code == 2
