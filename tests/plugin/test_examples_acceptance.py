"""Acceptance on the shipped ``examples/`` workspace with the real extractor and rules.

flake8 must print exactly the thesis scenario's findings — ROS001 on topic5's
publisher, ROS003 on topic8's subscription, ROS002 on node_1's topic1 and
node_2's topic7 subscriptions — whether it runs serially, with ``--jobs 2``,
under the spawn start method, or on one file at a time. Where those entities
are comes from the extracted graph; which findings are expected comes from the
scenario, not from the tool.
"""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from .conftest import EXAMPLES, REPO, clean_env, parse_flake8, run_flake8


def _site(graph, kind: str, topic: str, node_name: str | None = None) -> tuple[str, int, int]:
    sites = {(e.location.path, e.location.line, e.location.column) for node, e in graph.entities(kind)
             if e.name == topic and (node_name is None or node.name == node_name)}
    assert len(sites) == 1, f"expected one {kind} of {topic} on {node_name or 'any node'}, got {sites}"
    return sites.pop()


@pytest.fixture(scope="module")
def expected() -> list[tuple[str, int, int, str]]:
    from flake8_rosgraph.analysis import build_graph

    graph = build_graph(EXAMPLES)
    rows = [(*_site(graph, "publishers", "/topic5"), "ROS001"),
            (*_site(graph, "subscriptions", "/topic8"), "ROS003"),
            (*_site(graph, "subscriptions", "/topic1", "node_1"), "ROS002"),
            (*_site(graph, "subscriptions", "/topic7", "node_2"), "ROS002")]
    return sorted(("examples/" + path, line, column, code) for path, line, column, code in rows)


@pytest.fixture
def env(tmp_path: Path) -> dict[str, str]:
    return clean_env(ROSGRAPH_CACHE_DIR=str(tmp_path / "cache"))


@pytest.mark.parametrize("method, jobs", [("default", "1"), ("default", "2"), ("spawn", "2")])
def test_flake8_prints_exactly_the_scenario_findings(expected, env, method: str, jobs: str) -> None:
    result = run_flake8(["--select", "ROS", "--jobs", jobs, "examples"], REPO, env, start_method=method)
    assert parse_flake8(result.stdout) == expected, result.stdout + result.stderr
    assert result.returncode == 1


def test_one_file_at_a_time_gives_the_same_findings(expected, env) -> None:
    files = sorted({path for path, *_ in expected})
    rows = []
    for path in files:
        rows += parse_flake8(run_flake8(["--select", "ROS", path], REPO, env).stdout)
    assert sorted(rows) == expected
    clean = sorted(str(p.relative_to(REPO)) for p in EXAMPLES.rglob("*.py")
                   if str(p.relative_to(REPO)) not in files and "__pycache__" not in p.parts)[0]
    assert run_flake8(["--select", "ROS", clean], REPO, env).stdout == ""


def test_check_command_agrees(expected, env) -> None:
    result = subprocess.run([sys.executable, "-m", "flake8_rosgraph", "check", "examples"], cwd=REPO, env=env,
                            capture_output=True, text=True, timeout=600)
    assert parse_flake8(result.stdout) == expected, result.stdout + result.stderr
    assert result.returncode == 1
