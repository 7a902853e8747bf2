"""flake8 in a subprocess: worker processes (fork, spawn, forkserver) share one analysis per run."""
from __future__ import annotations

import json
import os
import shutil
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
def test_with_jobs_a_child_of_the_main_process_analyses_and_no_worker_waits(python: str, workspace: Path,
                                                                             tmp_path: Path, method: str) -> None:
    """flake8 -j2: the one analysis runs in a child flake8's main process forks before its pool
    (beside the workers, never in one), so no worker ever blocks on the cache lock; the findings
    are those of -j1."""
    if method != "fork" and _flake8_major(python) < 5:
        pytest.skip("flake8 4 checks files in one process unless its workers are forked")
    log = tmp_path / "analyses.log"
    child = subprocess.Popen([python, "-c", _FLAKE8_UNDER, method, "--isolated", "--jobs", "2",
                              "--select", "ROS", "."], cwd=workspace, env=fake_env(log),
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    stdout, stderr = child.communicate(timeout=600)
    assert parse_flake8(stdout) == EXPECTED_STANDARD, stderr
    [(pid, parent, role)] = [line.split()[:3] for line in analyses(log)]
    assert parent == str(child.pid) and pid != str(child.pid) and role == "-"


@pytest.mark.parametrize("method", ["fork", "spawn"])
def test_with_jobs_and_no_cache_the_child_hands_the_results_back(python: str, workspace: Path, tmp_path: Path,
                                                                 method: str) -> None:
    """Without a cache, flake8 -j2's analysis still runs in a child of the main process, which
    hands each file's results back: one analysis, in no worker."""
    log = tmp_path / "analyses.log"
    child = subprocess.Popen([python, "-c", _FLAKE8_UNDER, method, "--isolated", "--jobs", "2",
                              "--select", "ROS", "."], cwd=workspace, env=_uncached_env(tmp_path, log),
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    stdout, stderr = child.communicate(timeout=600)
    assert parse_flake8(stdout) == EXPECTED_STANDARD, stderr
    [(pid, parent)] = [line.split()[:2] for line in analyses(log)]
    assert parent == str(child.pid) and pid != str(child.pid)
    assert not (workspace / ".rosgraph-cache").exists()


@pytest.mark.skipif(shutil.which("taskset") is None or not hasattr(os, "sched_setaffinity"),
                    reason="needs taskset (util-linux) to give flake8 one core")
def test_with_jobs_on_one_core_the_main_process_analyses_in_a_thread(python: str, workspace: Path,
                                                                     tmp_path: Path) -> None:
    """With no second core for a child, flake8 -j2's main process analyses in a thread beside
    its workers: still one analysis, in no worker."""
    log = tmp_path / "analyses.log"
    child = subprocess.Popen(["taskset", "-c", "0", python, "-c", _FLAKE8_UNDER, "fork", "--isolated",
                              "--jobs", "2", "--select", "ROS", "."], cwd=workspace, env=fake_env(log),
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    stdout, stderr = child.communicate(timeout=600)
    assert parse_flake8(stdout) == EXPECTED_STANDARD, stderr
    assert [line.split()[0] for line in analyses(log)] == [str(child.pid)]


def _flake8_major(python: str) -> int:
    found = subprocess.run([python, "-c", "import flake8; print(flake8.__version__)"],
                           capture_output=True, text=True, check=True, timeout=120)
    return int(found.stdout.split(".")[0])


def _uncached_env(tmp_path: Path, log: Path) -> dict[str, str]:
    """The environment of a user whose signing key cannot be kept: no cache at all."""
    (tmp_path / "home").mkdir()
    (tmp_path / "home" / ".cache").write_text("not a folder: no signing key can be kept")
    return fake_env(log, HOME=str(tmp_path / "home"), XDG_CACHE_HOME=str(tmp_path / "home" / ".cache"))


@pytest.mark.parametrize("delay", ["0", "3"])
def test_with_one_job_a_child_analyses_while_flake8_checks(python: str, workspace: Path, tmp_path: Path,
                                                           delay: str) -> None:
    """flake8 -j1 checks the files itself while a child process analyses and hands the results
    back; the main process adds the findings afterwards, the same as one process finds, however
    long the analysis takes."""
    log = tmp_path / "analyses.log"
    child = subprocess.Popen([python, "-c", _FLAKE8_UNDER, "default", "--isolated", "--jobs", "1",
                              "--select", "ROS", "."], cwd=workspace,
                             env=fake_env(log, FAKE_ROSGRAPH_DELAY=delay),
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    stdout, stderr = child.communicate(timeout=600)
    assert parse_flake8(stdout) == EXPECTED_STANDARD, stderr
    [(pid, parent)] = [line.split()[:2] for line in analyses(log)]
    assert parent == str(child.pid) and pid != str(child.pid)


def test_a_run_of_one_file_analyses_beside_flake8s_checks_of_it(python: str, workspace: Path,
                                                                 tmp_path: Path) -> None:
    """pre-commit's one edited file: flake8's own checks of it overlap the analysis; a warm run
    reads the kept report in flake8's process, with no child."""
    log = tmp_path / "analyses.log"
    command = [python, "-c", _FLAKE8_UNDER, "default", "--isolated", "--jobs", "1", "--select", "ROS",
               "src/pkg_b/pkg_b/listener.py"]
    child = subprocess.Popen(command, cwd=workspace, env=fake_env(log), stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True)
    stdout, stderr = child.communicate(timeout=600)
    assert parse_flake8(stdout) == [("src/pkg_b/pkg_b/listener.py", 7, 10, "ROS003")], stderr
    [(pid, parent)] = [line.split()[:2] for line in analyses(log)]
    assert parent == str(child.pid) and pid != str(child.pid)
    warm = subprocess.run(command, cwd=workspace, env=fake_env(log),
                          capture_output=True, text=True, timeout=600)
    assert warm.stdout == stdout and len(analyses(log)) == 1


def test_with_one_job_and_no_cache_the_child_hands_the_results_back(python: str, workspace: Path,
                                                                     tmp_path: Path) -> None:
    """Without a cache, the child's results reach flake8 all the same: one analysis, in the child."""
    log = tmp_path / "analyses.log"
    child = subprocess.Popen([python, "-c", _FLAKE8_UNDER, "default", "--isolated", "--jobs", "1",
                              "--select", "ROS", "."], cwd=workspace, env=_uncached_env(tmp_path, log),
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    stdout, stderr = child.communicate(timeout=600)
    assert parse_flake8(stdout) == EXPECTED_STANDARD, stderr
    [(pid, parent)] = [line.split()[:2] for line in analyses(log)]
    assert parent == str(child.pid) and pid != str(child.pid)
    assert not (workspace / ".rosgraph-cache").exists()


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


def _niceness_after_yielding(_: object) -> int:
    from flake8_rosgraph import flake8_jobs

    flake8_jobs.yield_to_analysis()
    flake8_jobs.yield_to_analysis()  # once per worker, not once per deferred file
    return os.nice(0)


@pytest.mark.skipif(not hasattr(os, "nice"), reason="no process priorities on this platform")
@pytest.mark.parametrize("method", ["fork", "spawn"])
def test_pool_workers_yield_the_core_to_the_analysis(method: str) -> None:
    """A worker that defers its ROS results lowers its own priority once; flake8's main
    process, which runs the analysis, never does."""
    import multiprocessing

    from flake8_rosgraph import flake8_jobs

    before = os.nice(0)
    flake8_jobs.yield_to_analysis()
    assert os.nice(0) == before
    with multiprocessing.get_context(method).Pool(1) as pool:
        worker = pool.map(_niceness_after_yielding, [None])[0]
    assert worker == min(before + flake8_jobs.WORKER_NICENESS, 19)


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_a_sidecar_without_a_cache_is_written_from_the_one_analysis(python: str, workspace: Path,
                                                                    tmp_path: Path, jobs: str) -> None:
    """The SARIF sidecar reads the findings' related locations from the report in flake8's
    process: without a cache to pass it through, that process analyses (once), no child."""
    log = tmp_path / "analyses.log"
    result = run_flake8(["--jobs", jobs, "--select", "ROS", "--rosgraph-sarif", "out.sarif", "."], workspace,
                        _uncached_env(tmp_path, log), python)
    assert parse_flake8(result.stdout) == EXPECTED_STANDARD, result.stderr
    assert len(analyses(log)) == 1, analyses(log)
    results = json.loads((workspace / "out.sarif").read_text())["runs"][0]["results"]
    assert len(results) == len(EXPECTED_STANDARD)
