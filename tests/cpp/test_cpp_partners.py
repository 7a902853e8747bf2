"""C++ ends as partners of the Python rules: findings stay at Python ends, in every front end.

Uses the mixed workspace of ``tests/eval/cpp_mixed_workspace`` (a C++ driver
package and a Python monitor package) and small unit cases for the relocation.
"""
from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from flake8_rosgraph import cache
from flake8_rosgraph.analysis import build_graph
from flake8_rosgraph.cpp.reporting import at_python_ends
from flake8_rosgraph.findings import Finding, RuleConfig
from flake8_rosgraph.graph.json_out import to_json_obj
from flake8_rosgraph.graph.model import Location
from flake8_rosgraph.options import Settings

MIXED = Path(__file__).resolve().parents[1] / "eval" / "cpp_mixed_workspace"
MONITOR = "src/base_monitor/base_monitor/monitor.py"
CPP = Location("src/drv/src/talker.cpp", 12, 3)
PY_SUB = Location("src/mon/mon/listener.py", 9, 9)
PY_SUB_2 = Location("src/mon/mon/other.py", 4, 9)


@pytest.fixture
def mixed(tmp_path: Path) -> Path:
    root = tmp_path / "ws"
    shutil.copytree(MIXED, root)
    return root


def test_a_cpp_located_finding_moves_to_its_python_end():
    moved = at_python_ends([Finding(CPP, "ROS001", "topic '/chater' has no subscriber; did you mean '/chatter' "
                                                   "(subscribed at src/mon/mon/listener.py:9)?",
                                    ((PY_SUB, "subscription '/chatter'"),))])
    assert moved == [Finding(PY_SUB, "ROS001",
                             "C++ end src/drv/src/talker.cpp:12: topic '/chater' has no subscriber; did you mean "
                             "'/chatter' (subscribed at src/mon/mon/listener.py:9)?", ((CPP, "C++ end"),))]


def test_a_problem_the_python_end_already_reports_is_not_repeated():
    python_side = Finding(PY_SUB, "ROS003", "topic '/chatter' has no publisher; did you mean '/chater' "
                                            "(published at src/drv/src/talker.cpp:12)?", ((CPP, "publisher '/chater'"),))
    cpp_side = Finding(CPP, "ROS001", "topic '/chater' has no subscriber", ((PY_SUB, "subscription '/chatter'"),))
    assert at_python_ends([cpp_side, python_side]) == [python_side]


def test_a_cpp_only_problem_is_dropped_and_python_findings_are_untouched():
    cpp_only = Finding(CPP, "ROS002", "node '/talker' subscribes to topic '/x' that it publishes",
                       ((Location("src/drv/src/talker.cpp", 14, 3), "publisher '/x'"),))
    python = Finding(PY_SUB_2, "ROS001", "topic '/y' has no subscriber")
    assert at_python_ends([cpp_only, python]) == [python]


def test_mixed_workspace_graph_marks_cpp_nodes(mixed: Path):
    graph = build_graph(mixed)
    nodes = to_json_obj(graph)["nodes"]
    languages = {n["fqn"]: n.get("language") for n in nodes}
    assert languages == {"/alert_logger": None, "/base_monitor": None, "/base_driver": "cpp",
                         "/diagnostics_aggregator": "cpp", "/docking_server": "cpp"}
    driver = next(n for n in nodes if n["fqn"] == "/base_driver")
    assert {(p["topic"], p["type"], p["path"], p["line"]) for p in driver["publishers"]} >= {
        ("/battery", "sensor_msgs/msg/BatteryState", "src/base_driver/src/base_driver.cpp", 18)}
    assert driver["services"][0]["name"] == "/base_driver/reset"


def test_without_the_cpp_partners_the_python_ends_would_dangle(mixed: Path, monkeypatch):
    """The quiet ends are quiet because of the C++ partners, not by accident (every dangling end reported)."""
    import flake8_rosgraph.cpp.to_graph as to_graph
    from flake8_rosgraph.rules.ros003_subscription_without_publisher import SubscriptionWithoutPublisher
    from flake8_rosgraph.rules.ros008_service_client_without_server import ServiceClientWithoutServer
    from flake8_rosgraph.rules.ros009_action_client_without_server import ActionClientWithoutServer

    rules = [SubscriptionWithoutPublisher(True), ServiceClientWithoutServer(True), ActionClientWithoutServer(True)]

    def dangling() -> set[tuple[str, int]]:
        graph = build_graph(mixed)
        return {(f.code, f.location.line) for rule in rules for f in rule.check(graph, RuleConfig())}

    with_cpp = dangling()
    monkeypatch.setattr(to_graph, "cpp_graph", lambda root: ([], []))
    quiet_with_cpp = {("ROS003", 19), ("ROS003", 20), ("ROS003", 21), ("ROS008", 30), ("ROS009", 31)}
    assert quiet_with_cpp <= dangling()
    assert not quiet_with_cpp & with_cpp


def test_an_edit_to_a_cpp_file_changes_the_cache_key(mixed: Path):
    key = cache.cache_key(mixed, Settings())
    header = mixed / "src/base_driver/include/base_driver/base_driver.hpp"
    header.write_text(header.read_text() + "// edited\n")
    assert cache.cache_key(mixed, Settings()) != key


def test_check_and_sarif_report_only_python_locations(mixed: Path, tmp_path: Path):
    sarif = tmp_path / "out.sarif"
    done = subprocess.run([sys.executable, "-m", "flake8_rosgraph", "check", ".", "--root", ".",
                           "--format", "json", "--sarif", str(sarif), "--cache-dir", str(tmp_path / "c")],
                          cwd=mixed, capture_output=True, text=True, timeout=300)
    assert done.returncode == 1, done.stderr
    found = json.loads(done.stdout)
    findings = found["findings"] if isinstance(found, dict) else found
    assert {(f["code"], f["path"], f["line"]) for f in findings} == {
        ("ROS004", MONITOR, 23), ("ROS003", MONITOR, 25), ("ROS001", MONITOR, 29)}
    results = json.loads(sarif.read_text())["runs"][0]["results"]
    primary = {r["locations"][0]["physicalLocation"]["artifactLocation"]["uri"] for r in results}
    assert primary == {MONITOR}
    related = {loc["physicalLocation"]["artifactLocation"]["uri"] for r in results
               for loc in r.get("relatedLocations", ())}
    assert "src/base_driver/src/diagnostics_node.cpp" in related


def test_flake8_reports_at_python_ends_and_nothing_for_cpp_files(mixed: Path, tmp_path: Path):
    cpp = "src/base_driver/src/diagnostics_node.cpp"
    done = subprocess.run([sys.executable, "-m", "flake8", "--isolated", "-j", "1", "--select", "ROS",
                           "--rosgraph-root", str(mixed), "--rosgraph-cache-dir", str(tmp_path / "c"),
                           MONITOR, cpp], cwd=mixed, capture_output=True, text=True, timeout=300)
    lines = sorted(line.split(" ")[0] for line in done.stdout.splitlines() if " ROS" in line)
    assert lines == [f"{MONITOR}:23:9:", f"{MONITOR}:25:9:", f"{MONITOR}:29:22:"], done.stdout + done.stderr
