"""The Mermaid and DOT views: what they draw, escaping, and the real parsers accept them.

Graphviz (``dot -Tsvg``) and Mermaid's own parser (``mermaid.parse`` from the
npm package, run in the headless browser) judge the syntax; ``.ci/run``
installs both, and the tests skip with the reason where either is missing.
"""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from .browser import console_errors, open_page

from flake8_rosgraph.findings import Finding
from flake8_rosgraph.graph.mermaid import to_mermaid
from flake8_rosgraph.graph.model import Entity, Location, RosGraph, RosNode
from flake8_rosgraph.rules.exempt import ExemptNames

REPO = Path(__file__).resolve().parents[2]
EXAMPLES = REPO / "examples"
MERMAID_JS = os.environ.get("ROSGRAPH_MERMAID_JS")


def loc(line: int, path: str = "pkg/nodes.py") -> Location:
    return Location(path, line, 9)


def odd_graph() -> RosGraph:
    return RosGraph([
        RosNode("talker", "/", loc(1), entities=[
            Entity("publishers", "/chatter", loc(2), type="std_msgs/msg/String"),
            Entity("publishers", '/we"ird#name;<b>', loc(3)),
            Entity("timers", None, loc(4), period=0.5),
            Entity("publishers", "/rosout", loc(5)),
        ]),
        RosNode("listener", "/", loc(6), entities=[
            Entity("subscriptions", "/chatter", loc(7), type="std_msgs/msg/String"),
            Entity("subscriptions", "/chater", loc(8), type="std_msgs/msg/String"),
            Entity("clients", "/add", loc(9)),
            Entity("action_clients", None, loc(10)),
        ]),
        RosNode(None, None, loc(11), entities=[Entity("services", "/add", loc(12))]),
    ])


def test_mermaid_structure_and_escaping():
    near = Finding(loc(8), "ROS003", "topic '/chater' has no publisher; did you mean '/chatter'?",
                   ((loc(2), "published here"),))
    text = to_mermaid(odd_graph(), [near], ExemptNames.build())
    lines = text.splitlines()
    assert lines[0] == "flowchart LR"
    assert "%% 1 infrastructure names hidden" in lines[1]  # /rosout
    assert not any("rosout" in line for line in lines[2:])
    assert '(["/talker<br>timer 0.5 s"])' in text
    assert "#34;" in text and "#35;" in text and "#59;" in text and "#60;" in text  # " # ; <
    assert '"/we' in text and "<b>" not in text
    assert any('-. "did you mean?" .-' in line for line in lines)  # the near-miss pair is linked
    assert any("-.->" in line for line in lines)  # a client edge is dotted
    assert text == to_mermaid(odd_graph(), [near], ExemptNames.build())


def run_cli(*args: str) -> str:
    return subprocess.run([sys.executable, "-m", "flake8_rosgraph", "graph", *args],
                          capture_output=True, text=True, timeout=300, check=True).stdout


@pytest.mark.skipif(shutil.which("dot") is None, reason="Graphviz is not installed (Debian package graphviz)")
@pytest.mark.parametrize("workspace", ["examples", "odd"])
def test_graphviz_renders_the_dot(workspace, tmp_path):
    if workspace == "examples":
        text = run_cli(str(EXAMPLES), "--format", "dot")
    else:
        from flake8_rosgraph.graph.dot import to_dot
        text = to_dot(odd_graph(), exempt=ExemptNames.build())
    svg = subprocess.run(["dot", "-Tsvg"], input=text, capture_output=True, text=True, timeout=120, check=True)
    assert svg.stdout.lstrip().startswith("<?xml") and "Legend" in svg.stdout


@pytest.mark.skipif(MERMAID_JS is None or not Path(MERMAID_JS).is_file(),
                    reason="ROSGRAPH_MERMAID_JS does not name mermaid.min.js (npm install mermaid; .ci/run does)")
def test_mermaid_parser_accepts_the_output(browser, tmp_path):
    checker = tmp_path / "check.html"
    checker.write_text(f'<!DOCTYPE html><html><body><script src="{Path(MERMAID_JS).resolve().as_uri()}">'
                       "</script></body></html>")
    open_page(browser, checker)
    texts = {"examples": run_cli(str(EXAMPLES), "--format", "mermaid"),
             "odd": to_mermaid(odd_graph(), exempt=ExemptNames.build())}
    for name, text in texts.items():
        verdict = browser.execute_async_script("""
            const done = arguments[arguments.length - 1];
            mermaid.parse(arguments[0]).then(() => done('ok'), (e) => done(String(e && e.message || e)));
        """, text)
        assert verdict == "ok", (name, verdict, text)
    broken = browser.execute_async_script("""
        const done = arguments[arguments.length - 1];
        mermaid.parse('flowchart LR\\n  a[["x"] --> b').then(() => done('ok'), () => done('error'));
    """)
    assert broken == "error"  # the check can fail
    assert console_errors(browser) == []


def test_launch_option_shows_only_what_the_launch_file_starts(tmp_path):
    from .fleet import write_fleet
    write_fleet(tmp_path)
    launch = tmp_path / "src" / "control" / "launch" / "control.launch.py"
    shown = json.loads(run_cli(str(tmp_path), "--format", "json", "--launch", str(launch)))
    assert shown["nodes"] and all(n["namespace"] == "/control_ns" for n in shown["nodes"])
    assert all("launch" in n for n in shown["nodes"])
    mermaid = run_cli(str(tmp_path), "--format", "mermaid", "--launch", str(launch))
    assert "/control_ns/control_stage0" in mermaid and "/planning_stage0" not in mermaid
