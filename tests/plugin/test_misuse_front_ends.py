"""The rclpy-misuse rules (ROS101-ROS106) through the ``check`` command and SARIF, on a real
eval package: the usage facts survive the launch-aware graph the front ends judge."""
from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from flake8_rosgraph import check_cli

from .test_check_cli import check

CASE = Path(__file__).resolve().parents[1] / "eval" / "ros101_blocking_call"


@pytest.fixture
def package(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    shutil.copytree(CASE / "map_sync", tmp_path / "ws" / "map_sync")
    monkeypatch.chdir(tmp_path / "ws")
    return tmp_path


def test_check_reports_the_chain_in_sarif(package: Path, capsys: pytest.CaptureFixture[str]) -> None:
    sarif = package / "out.sarif"
    status = check(["map_sync", "--root", ".", "--select", "ROS101", "--cache-dir",
                    str(package / "cache"), "--sarif", str(sarif)])
    assert status == check_cli.EXIT_FINDINGS
    out = capsys.readouterr().out
    assert "map_sync/map_sync/sync_node.py:20:20: ROS101 `client.call()` reached from subscription " \
           "callback `SyncNode.on_update` via `requests.refresh()` → `fetch_map()`" in out
    run = json.loads(sarif.read_text())["runs"][0]
    result = next(r for r in run["results"]
                  if r["locations"][0]["physicalLocation"]["artifactLocation"]["uri"].endswith("/map_sync/sync_node.py"))
    related = [(loc["physicalLocation"]["artifactLocation"]["uri"].rsplit("/", 1)[-1],
                loc["physicalLocation"]["region"]["startLine"]) for loc in result["relatedLocations"]]
    assert related == [("sync_node.py", 17), ("requests.py", 11), ("requests.py", 7)]
    assert "ROS101" in {rule["id"] for rule in run["tool"]["driver"]["rules"]}


def test_the_misuse_rules_can_be_ignored(package: Path, capsys: pytest.CaptureFixture[str]) -> None:
    status = check(["map_sync", "--root", ".", "--select", "ROS1", "--ignore", "ROS101",
                    "--cache-dir", str(package / "cache")])
    assert status == 0
    assert capsys.readouterr().out == ""
