"""flake8 in a subprocess: worker processes (fork, spawn, forkserver) share one analysis per run."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from .conftest import _FLAKE8_UNDER, EXPECTED_STANDARD, analyses, fake_env, parse_flake8, run_flake8


@pytest.fixture(params=[pytest.param("current", id="flake8-current"),
                        pytest.param("4.0.1", id="flake8-4.0.1", marks=pytest.mark.slow)])
def python(request: pytest.FixtureRequest) -> str:
    """The interpreter whose flake8 to run: this one, or one with flake8 4.0.1."""
    if request.param == "current":
        return sys.executable
    return str(request.getfixturevalue("flake8_401_venv"))


@pytest.mark.parametrize("method, jobs", [("default", "1"), ("default", "2"), ("fork", "2"),
                                          ("spawn", "2"), ("forkserver", "2")])
def test_same_findings_and_one_analysis_per_run(python: str, workspace: Path, tmp_path: Path,
                                                method: str, jobs: str) -> None:
    log = tmp_path / "analyses.log"
    result = run_flake8(["--jobs", jobs, "--select", "ROS", "."], workspace, fake_env(log), python, method)
    assert parse_flake8(result.stdout) == EXPECTED_STANDARD, result.stderr
    assert result.returncode == 1
    assert len(analyses(log)) == 1, analyses(log)
    again = run_flake8(["--jobs", jobs, "--select", "ROS", "."], workspace, fake_env(log), python, method)
    assert again.stdout == result.stdout
    assert len(analyses(log)) == 1  # the warm run reads the cache


def test_only_the_changed_files_passed(python: str, workspace: Path, tmp_path: Path) -> None:
    log = tmp_path / "analyses.log"
    result = run_flake8(["--select", "ROS", "src/pkg_b/pkg_b/listener.py", "src/pkg_a/pkg_a/__init__.py"],
                        workspace, fake_env(log), python)
    assert parse_flake8(result.stdout) == [("src/pkg_b/pkg_b/listener.py", 7, 10, "ROS003")]


def test_debug_environment_variable_shows_the_traceback(python: str, workspace: Path, tmp_path: Path) -> None:
    (workspace / "src/pkg_a/pkg_a/broken.py").write_text("# FAKE_CRASH\n")
    log = tmp_path / "analyses.log"
    quiet = run_flake8(["--select", "ROS", "."], workspace, fake_env(log), python)
    assert [row[3] for row in parse_flake8(quiet.stdout)] == ["ROS000"]
    loud = run_flake8(["--select", "ROS", "."], workspace, fake_env(log, ROSGRAPH_DEBUG="1"), python)
    assert "ROS000" not in loud.stdout
    assert "RuntimeError: fake analysis crashed" in loud.stdout + loud.stderr
    assert loud.returncode != 0


def test_sidecar_holds_what_the_terminal_shows(python: str, workspace: Path, tmp_path: Path) -> None:
    log = tmp_path / "analyses.log"
    plain = run_flake8(["--jobs", "2", "."], workspace, fake_env(log), python)
    with_sidecar = run_flake8(["--jobs", "2", "--rosgraph-sarif", "out.sarif", "."], workspace, fake_env(log), python)
    assert with_sidecar.stdout == plain.stdout
    results = json.loads((workspace / "out.sarif").read_text())["runs"][0]["results"]
    rows = sorted((r["locations"][0]["physicalLocation"]["artifactLocation"]["uri"],
                   r["locations"][0]["physicalLocation"]["region"]["startLine"],
                   r["locations"][0]["physicalLocation"]["region"]["startColumn"], r["ruleId"]) for r in results)
    assert rows == parse_flake8(plain.stdout)
    assert {row[3] for row in rows} >= {"ROS001", "ROS002", "ROS003"}


@pytest.mark.parametrize("method", ["fork", "spawn", "forkserver"])
def test_with_jobs_the_main_process_analyses_and_no_worker_waits(python: str, workspace: Path,
                                                                 tmp_path: Path, method: str) -> None:
    """flake8 -j2: the one analysis runs in flake8's main process (beside the workers), so
    no worker ever blocks on the cache lock; the findings are those of -j1."""
    log = tmp_path / "analyses.log"
    child = subprocess.Popen([python, "-c", _FLAKE8_UNDER, method, "--isolated", "--jobs", "2",
                              "--select", "ROS", "."], cwd=workspace, env=fake_env(log),
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    stdout, stderr = child.communicate(timeout=600)
    assert parse_flake8(stdout) == EXPECTED_STANDARD, stderr
    assert [line.split()[0] for line in analyses(log)] == [str(child.pid)]


def test_noqa_on_a_later_line_of_the_statement_works_the_same_with_jobs(python: str, workspace: Path,
                                                                         tmp_path: Path) -> None:
    """Results added by the main process get flake8's own ``noqa`` line for their position."""
    talker = workspace / "src/pkg_a/pkg_a/talker.py"
    talker.write_text(talker.read_text() + "    node.create_publisher(String, 'quiet',\n"
                                           "                          10)  # noqa: ROS001\n"
                                           "    node.create_publisher(String, 'loud',\n"
                                           "                          10)\n")
    log = tmp_path / "analyses.log"
    serial = run_flake8(["--jobs", "1", "--select", "ROS", "."], workspace, fake_env(log), python)
    parallel = run_flake8(["--jobs", "2", "--select", "ROS", "."], workspace, fake_env(log), python)
    assert parallel.stdout == serial.stdout, (serial.stderr, parallel.stderr)
    assert ("src/pkg_a/pkg_a/talker.py", 11, 10, "ROS001") in parse_flake8(parallel.stdout)


@pytest.mark.parametrize("jobs", ["1", "2"])
@pytest.mark.parametrize("select", [["--select", "E,W"], ["--extend-ignore", "ROS"], ["--select", "F,ROS9"]])
def test_no_analysis_when_no_ros_code_can_be_reported(python: str, workspace: Path, tmp_path: Path,
                                                      jobs: str, select: list[str]) -> None:
    log = tmp_path / "analyses.log"
    result = run_flake8(["--jobs", jobs, *select, "."], workspace, fake_env(log), python)
    assert result.returncode in (0, 1), result.stderr
    assert "ROS" not in result.stdout
    assert analyses(log) == []
    assert not (workspace / ".rosgraph-cache").exists()
