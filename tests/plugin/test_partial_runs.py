"""Changed-files runs (pre-commit, pull-request checks): a broken connection is shown in each checked file
holding one of its ends, with the real extractor and rules, through real flake8 and ``check``; a full run
shows each problem once."""
from __future__ import annotations

import json
import subprocess
import sys
from argparse import Namespace
from pathlib import Path

import pytest

from flake8_rosgraph.findings import Finding
from flake8_rosgraph.graph.model import Location
from flake8_rosgraph.partial_runs import CheckedFiles, shown_findings

from .conftest import clean_env, parse_flake8, run_flake8, write_tree

NODE = """\
import rclpy
from rclpy.node import Node
from std_msgs.msg import {type}


class {cls}(Node):
    def __init__(self):
        super().__init__('{node}')
        self.create_{kind}({type}, '{topic}'{callback}, 10)
        self.create_{ack_kind}(String, 'ack'{ack_callback}, 10)


def main():
    rclpy.init()
    rclpy.spin({cls}())
"""


def node_file(cls: str, node: str, kind: str, topic: str, type: str = "String") -> str:
    publishing = kind == "publisher"
    return NODE.format(cls=cls, node=node, kind=kind, topic=topic,
                       type=type if type == "String" else f"String, {type}",
                       callback="" if publishing else ", print",
                       ack_kind="subscription" if publishing else "publisher",
                       ack_callback=", print" if publishing else "").replace(
        f"self.create_{kind}(String, {type}", f"self.create_{kind}({type}")


TALKER = "src/chatter/chatter/talker.py"
RECORDER = "src/chatter/chatter/recorder.py"
GAUGE = "src/chatter/chatter/gauge.py"


@pytest.fixture(scope="module")
def ws(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """talker publishes /chatter (String); listener listens right; recorder misspelt it; gauge wants Int32."""
    root = tmp_path_factory.mktemp("partial") / "ws"
    write_tree(root, {
        "src/chatter/package.xml": "<package format='3'><name>chatter</name></package>\n",
        "src/chatter/chatter/__init__.py": "",
        TALKER: node_file("Talker", "talker", "publisher", "chatter"),
        "src/chatter/chatter/listener.py": node_file("Listener", "listener", "subscription", "chatter"),
        RECORDER: node_file("Recorder", "recorder", "subscription", "chater"),
        GAUGE: node_file("Gauge", "gauge", "subscription", "chatter", type="Int32"),
    })
    subprocess.run(["git", "init", "-q", str(root)], check=True)
    return root


@pytest.fixture
def env(tmp_path: Path) -> dict[str, str]:
    return clean_env(ROSGRAPH_CACHE_DIR=str(tmp_path / "cache"))


def flake8(ws: Path, env: dict[str, str], *paths: str) -> list[tuple[str, int, int, str]]:
    result = run_flake8(["--select", "ROS", *paths], ws, env)
    assert result.returncode in (0, 1), result.stderr
    return parse_flake8(result.stdout)


def test_a_full_run_reports_each_problem_once(ws: Path, env: dict[str, str]) -> None:
    assert flake8(ws, env, ".") == [(GAUGE, 9, 9, "ROS004"), (RECORDER, 9, 9, "ROS003")]


def test_checking_only_the_partner_file_shows_the_problems_there(ws: Path, env: dict[str, str]) -> None:
    result = run_flake8(["--select", "ROS", TALKER], ws, env)
    assert parse_flake8(result.stdout) == [(TALKER, 9, 9, "ROS003"), (TALKER, 9, 9, "ROS004")]
    assert (f"(reported at {RECORDER}:9, which this run does not check)") in result.stdout
    assert "did you mean '/chatter'" in result.stdout


def test_checking_both_ends_shows_each_problem_at_its_own_end(ws: Path, env: dict[str, str]) -> None:
    assert flake8(ws, env, TALKER, RECORDER, GAUGE) == [(GAUGE, 9, 9, "ROS004"), (RECORDER, 9, 9, "ROS003")]
    # the gauge is not checked: its type mismatch shows at the talker, the near miss stays at the recorder
    assert flake8(ws, env, TALKER, RECORDER) == [(RECORDER, 9, 9, "ROS003"), (TALKER, 9, 9, "ROS004")]


def test_excluded_ends_count_as_unchecked(ws: Path, env: dict[str, str]) -> None:
    # ROS004's other ends are every end that agrees on the type: the listener is one of them
    rows = flake8(ws, env, "--extend-exclude", "recorder.py,gauge.py", ".")
    assert rows == [("src/chatter/chatter/listener.py", 9, 9, "ROS004"),
                    (TALKER, 9, 9, "ROS003"), (TALKER, 9, 9, "ROS004")]


def test_check_cli_mirrors_the_same_way(ws: Path, env: dict[str, str]) -> None:
    result = subprocess.run([sys.executable, "-m", "flake8_rosgraph", "check", "--format", "json", TALKER],
                            cwd=ws, env=env, capture_output=True, text=True, timeout=600)
    found = json.loads(result.stdout)["findings"]
    assert [(f["code"], f["path"], f["line"]) for f in found] == [("ROS003", TALKER, 9), ("ROS004", TALKER, 9)]
    assert found[0]["related"][0] == {"path": RECORDER, "line": 9, "column": 9,
                                      "label": "where the rule reports it"}


def finding(path: str, code: str = "ROS004", *related: str) -> Finding:
    return Finding(Location(path, 3, 5), code, "m", tuple((Location(r, 7, 1), "end") for r in related))


def test_shown_findings_mirror_only_broken_connections_once_per_file() -> None:
    findings = [finding("a.py", "ROS004", "b.py", "b.py", "c.py"), finding("a.py", "ROS007", "b.py")]
    shown = shown_findings(findings, lambda path: path == "b.py")
    assert [(f.location.path, f.code) for f in shown] == [("b.py", "ROS004")]
    assert shown[0].related[0] == (Location("a.py", 3, 5), "where the rule reports it")
    assert shown_findings(findings, lambda path: True) == findings


def test_no_mirror_where_the_other_end_already_reports_the_pair() -> None:
    # a near miss whose both ends dangle: each end is reported, pointing at the other
    ros001 = Finding(Location("a.py", 3, 5), "ROS001", "m", ((Location("b.py", 7, 1), "subscription"),))
    ros003 = Finding(Location("b.py", 7, 1), "ROS003", "m", ((Location("a.py", 3, 5), "publisher"),))
    assert shown_findings([ros001, ros003], lambda path: path == "a.py") == [ros001]


def test_checked_files_follow_flake8s_expansion(tmp_path: Path) -> None:
    options = Namespace(filenames=[str(tmp_path / "pkg"), str(tmp_path / "one.py")], exclude=["build", "*_pb2.py"],
                        extend_exclude=[], filename=["*.py"])
    checked = CheckedFiles.from_flake8(options)
    assert tmp_path / "pkg" / "a" / "node.py" in checked
    assert tmp_path / "one.py" in checked
    assert tmp_path / "two.py" not in checked
    assert tmp_path / "pkg" / "build" / "node.py" not in checked
    assert tmp_path / "pkg" / "msg_pb2.py" not in checked
    assert tmp_path / "pkg" / "node.cpp" not in checked
    assert CheckedFiles.from_flake8(Namespace(filenames=["-"])) is None
    assert CheckedFiles.from_flake8(Namespace()) is None
