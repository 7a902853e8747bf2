"""`flake8-rosgraph graph` with launch files, as a user runs it (subprocess)."""
import json
import subprocess
import sys
from pathlib import Path

WS = Path(__file__).parent / "ws"


def graph(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "flake8_rosgraph", "graph", str(WS), *args],
                          capture_output=True, text=True, timeout=120)


def test_code_graph_lists_every_launch_system():
    out = json.loads(graph().stdout)
    files = [s["launch_file"] for s in out["systems"]]
    assert "src/demo_bringup/launch/system.launch.xml" in files
    assert "src/demo_bringup/launch/system.launch.py" in files
    assert all("launch" not in n for n in out["nodes"])  # the code-level graph itself


def test_launch_option_prints_the_instantiated_system():
    result = graph("--launch", str(WS / "src/demo_bringup/launch/system.launch.xml"))
    assert result.returncode == 0, result.stderr
    nodes = {n["fqn"]: n for n in json.loads(result.stdout)["nodes"]}
    speaker = nodes["/r1/speaker"]
    assert [p["topic"] for p in speaker["publishers"]] == ["/r1/chatter"]
    assert speaker["launch"]["file"] == "src/demo_bringup/launch/system.launch.xml"
    # the remap heard -> chatter connects the listener in namespace r1
    assert [s["topic"] for s in nodes["/r1/listener"]["subscriptions"]] == ["/r1/chatter"]


def test_launch_option_rejects_a_file_that_is_no_launch_file():
    result = graph("--launch", str(WS / "nonexistent.launch.py"))
    assert result.returncode == 2
    assert "is not a launch file" in result.stderr
