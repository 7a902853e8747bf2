"""The workflow around the rules, tried as a user would: configuration, adoption, annotations, commands.

Everything runs the real analysis on a copy of the shipped example workspace
(four findings in the thesis package), through the installed command line and
the real flake8, in subprocesses.
"""
from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from .conftest import EXAMPLES, clean_env, parse_flake8, validate_sarif

PRODUCERS = "src/thesis_graph/thesis_graph/producers.py"
CONSUMERS = "src/thesis_graph/thesis_graph/consumers.py"
EXPECTED = [(CONSUMERS, 20, 9, "ROS003"), (PRODUCERS, 17, 9, "ROS002"), (PRODUCERS, 49, 9, "ROS001"),
            (PRODUCERS, 52, 9, "ROS002")]


def tool(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "flake8_rosgraph", *args], cwd=cwd, capture_output=True,
                          text=True, timeout=300, env=clean_env())


def flake8(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "flake8", "--select", "ROS", *args], cwd=cwd,
                          capture_output=True, text=True, timeout=300, env=clean_env())


@pytest.fixture
def ws(tmp_path: Path) -> Path:
    root = tmp_path / "ws"
    shutil.copytree(EXAMPLES, root)
    (root / ".git").mkdir()
    return root


def rows(result: subprocess.CompletedProcess[str]) -> list[tuple[str, int, int, str]]:
    return parse_flake8(result.stdout)


def test_check_and_flake8_read_the_same_flake8_config(ws: Path) -> None:
    (ws / "setup.cfg").write_text(
        "[flake8]\n"
        "rosgraph-external-topics = /topic5\n"
        f"per-file-ignores =\n    {CONSUMERS}: ROS003\n")
    expected = [(PRODUCERS, 17, 9, "ROS002"), (PRODUCERS, 52, 9, "ROS002")]
    assert rows(tool("check", ".", cwd=ws)) == expected
    assert rows(flake8(".", cwd=ws)) == expected


def test_pyproject_table_for_check(ws: Path) -> None:
    (ws / "pyproject.toml").write_text('[tool.flake8-rosgraph]\nignore = ["ROS002"]\n')
    assert [r[3] for r in rows(tool("check", ".", cwd=ws))] == ["ROS003", "ROS001"]
    # the command line wins over the file
    assert [r[3] for r in rows(tool("check", "--ignore", "ROS001", ".", cwd=ws))] == ["ROS003", "ROS002", "ROS002"]


@pytest.mark.parametrize("table, key", [('colour = "red"', "colour"), ("select = 5", "select"),
                                        ('debug = "maybe"', "debug")])
def test_a_bad_configuration_value_names_the_file_and_key(ws: Path, table: str, key: str) -> None:
    (ws / "pyproject.toml").write_text(f"[tool.flake8-rosgraph]\n{table}\n")
    result = tool("check", ".", cwd=ws)
    assert result.returncode == 2 and result.stdout == ""
    (line,) = result.stderr.splitlines()
    assert "pyproject.toml" in line and f"[tool.flake8-rosgraph] {key}" in line


def test_file_noqa_marker_is_honoured_like_flake8(ws: Path) -> None:
    path = ws / PRODUCERS
    path.write_text("# flake8: noqa\n" + path.read_text())
    assert rows(tool("check", ".", cwd=ws)) == [(CONSUMERS, 20, 9, "ROS003")]
    assert rows(flake8(".", cwd=ws)) == [(CONSUMERS, 20, 9, "ROS003")]


def test_exit_zero_and_github_annotations(ws: Path) -> None:
    result = tool("check", "--exit-zero", "--format", "github", ".", cwd=ws)
    assert result.returncode == 0
    lines = result.stdout.splitlines()
    assert len(lines) == 4
    assert f"::warning file={CONSUMERS},line=20,col=9,title=ROS003::ROS003 topic '/topic8'" in lines[0]
    assert all(line.startswith("::warning ") for line in lines)


def test_github_annotations_escape_what_workflow_commands_read(ws: Path) -> None:
    from flake8_rosgraph.check_cli import _github_escape

    assert _github_escape("50% done\nnext") == "50%25 done%0Anext"
    assert _github_escape("a/b.py:3, x", property_value=True) == "a/b.py%3A3%2C x"


def test_baseline_hides_old_findings_across_line_shifts_and_shows_new_ones(ws: Path) -> None:
    assert tool("check", "--write-baseline", "baseline.json", ".", cwd=ws).returncode == 1
    data = json.loads((ws / "baseline.json").read_text())
    assert data["schema"] == "flake8-rosgraph-baseline/1" and len(data["findings"]) == 4
    producers = ws / PRODUCERS
    producers.write_text('"""Producers of the thesis graph."""\n\n\n' + producers.read_text())
    clean = tool("check", "--baseline", "baseline.json", ".", cwd=ws)
    assert (clean.returncode, clean.stdout) == (0, "")
    text = producers.read_text().replace("'topic2'", "'topic22'")  # a new typo: nobody subscribes topic22
    producers.write_text(text)
    new = tool("check", "--baseline", "baseline.json", ".", cwd=ws)
    assert new.returncode == 1
    assert {r[3] for r in rows(new)} >= {"ROS001"} and all(r[0] == PRODUCERS or r[3] == "ROS003" for r in rows(new))
    assert any("topic22" in line for line in new.stdout.splitlines())
    broken = tool("check", "--baseline", "missing.json", ".", cwd=ws)
    assert broken.returncode == 2 and "missing.json" in broken.stderr


def test_sarif_of_check_says_whether_the_run_succeeded(ws: Path) -> None:
    ok = tool("check", "--sarif", "out.sarif", ".", cwd=ws)
    assert ok.returncode == 1
    log = json.loads((ws / "out.sarif").read_text())
    validate_sarif(log)
    assert log["runs"][0]["invocations"][0]["executionSuccessful"] is True
    (ws / "bad.toml").write_text("[functions.\n")
    failed = tool("check", "--stubs", "bad.toml", "--sarif", "failed.sarif", ".", cwd=ws)
    assert failed.returncode == 2
    assert json.loads((ws / "failed.sarif").read_text())["runs"][0]["invocations"][0]["executionSuccessful"] is False


def test_partner_paths_are_relative_to_where_the_user_is(ws: Path) -> None:
    src = ws / "src"
    result = tool("check", "--root", str(ws), ".", cwd=src)
    loop = next(line for line in result.stdout.splitlines() if ":17:" in line)
    assert loop.startswith("thesis_graph/thesis_graph/producers.py:17:9: ROS002")
    assert "at thesis_graph/thesis_graph/producers.py:26" in loop
    flake8_loop = next(line for line in flake8(".", cwd=src).stdout.splitlines() if ":17:" in line)
    assert "at thesis_graph/thesis_graph/producers.py:26" in flake8_loop


def test_rules_and_explain_commands(tmp_path: Path) -> None:
    table = tool("rules", cwd=tmp_path)
    assert table.returncode == 0
    lines = table.stdout.splitlines()
    assert lines[0].split()[:4] == ["code", "name", "level", "default"]
    assert any(line.split()[:4] == ["ROS010", "unresolved-name", "note", "off"] for line in lines)
    listed = json.loads(tool("rules", "--format", "json", cwd=tmp_path).stdout)
    assert {"code": "ROS003", "name": "subscription-without-publisher"}.items() <= listed[2].items()
    doc = tool("explain", "ros003", cwd=tmp_path)
    assert doc.stdout.startswith("# ROS003 subscription-without-publisher")
    assert "### Why is this bad?" in doc.stdout and "### Use instead" in doc.stdout
    unknown = tool("explain", "ROS999", cwd=tmp_path)
    assert unknown.returncode == 2 and "ROS999" in unknown.stderr


def test_an_editor_buffer_is_analysed_instead_of_the_file_on_disk(ws: Path) -> None:
    """Editors (VS Code's flake8, pylsp) send the unsaved buffer on stdin with --stdin-display-name."""
    path = ws / PRODUCERS
    saved = path.read_text()
    # the user fixes the unsubscribed /topic5 publisher and, two lines higher, adds a typo'd one
    buffer = saved.replace("'topic5'", "'topic4'")
    anchor = buffer.splitlines(keepends=True)
    insert_at = next(i for i, line in enumerate(anchor) if "'topic4'" in line)
    typo = anchor[insert_at].replace("'topic4'", "'topic44'")
    buffer = "".join(anchor[:insert_at] + ["\n", typo] + anchor[insert_at:])
    result = subprocess.run([sys.executable, "-m", "flake8", "--select", "ROS", "--stdin-display-name", PRODUCERS,
                             "-"], cwd=ws, input=buffer, capture_output=True, text=True, timeout=300,
                            env=clean_env())
    found = rows(result)
    typo_line = insert_at + 2
    assert (PRODUCERS, typo_line, 9, "ROS001") in found, result.stdout + result.stderr
    assert not any("topic5" in line for line in result.stdout.splitlines())
    assert path.read_text() == saved  # nothing written
    # the saved file is still judged as saved, and shares the cache as before
    assert (PRODUCERS, 49, 9, "ROS001") in rows(flake8(PRODUCERS, cwd=ws))
