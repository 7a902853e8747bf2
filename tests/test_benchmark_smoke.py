"""Smoke tests of the speed benchmark (``benchmarks/``): it runs and reports, without timing asserts.

Timings depend on the machine, so nothing here asserts a speed. What is checked
is what the numbers rest on: the script measures every step on a tiny
workspace and leaves that workspace untouched, the flake8 baseline really runs
without the plugin, the synthetic workspace is valid, deterministic code whose
graph grows with the scale, and the log-log fit recovers a known exponent.
"""
from __future__ import annotations

import ast
import json
import re
import subprocess
import sys
from pathlib import Path

import pytest
from pyflakes.api import check as pyflakes_check
from pyflakes.reporter import Reporter

from flake8_rosgraph.analysis import build_graph

BENCH_DIR = Path(__file__).resolve().parent.parent / "benchmarks"
sys.path.insert(0, str(BENCH_DIR))

import growth  # noqa: E402  (benchmarks/ is a folder of scripts, not a package)
import synth  # noqa: E402
from robustness.metadata_workspace import TALKER  # noqa: E402  (tests/ is on the path: no __init__)

LISTENER = '''\
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Listener(Node):
    def __init__(self):
        super().__init__('listener')
        self.sub = self.create_subscription(String, 'chatter', self.on_msg, 10)
        self.heard = self.create_subscription(String, 'unheard', self.on_msg, 10)
        self.status = self.create_subscription(String, 'status', self.on_msg, 10)

    def on_msg(self, msg):
        self.get_logger().info(msg.data)


def main():
    rclpy.init()
    rclpy.spin(Listener())
'''


def _tiny_workspace(root: Path) -> dict[Path, bytes]:
    package = root / "src" / "chat"
    (package / "chat").mkdir(parents=True)
    (package / "package.xml").write_text("<package format='3'><name>chat</name></package>\n")
    files = {package / "chat" / "__init__.py": b"",
             package / "chat" / "talker.py": TALKER.replace(
                 "        self.timer", "        self.status = self.create_publisher(String, 'status', 10)\n"
                 "        self.timer").encode(),
             package / "chat" / "listener.py": LISTENER.encode()}
    for path, data in files.items():
        path.write_bytes(data)
    return files


def test_run_prints_the_table_and_leaves_the_workspace_alone(tmp_path: Path) -> None:
    workspace = tmp_path / "ws"
    files = _tiny_workspace(workspace)
    out = tmp_path / "bench.json"
    # A stand-in for ros2inspector: what the row needs of it is its command line and its JSON.
    peer = tmp_path / "fake-ros2inspector"
    peer.write_text(f"#!{sys.executable}\nimport sys\n"
                    "assert sys.argv[1:] == ['--quiet', 'graph', 'comms', '--path', '.', '--format', 'json', "
                    "'--no-cache'], sys.argv\n"
                    "print('{\"nodes\": [1, 2, 3], \"edges\": [1]}')\n")
    peer.chmod(0o755)
    done = subprocess.run([sys.executable, str(BENCH_DIR / "run.py"), str(workspace), "--runs", "1",
                           "--json", str(out), "--peer", str(peer)],
                          capture_output=True, text=True, timeout=300, check=False)
    assert done.returncode == 0, done.stderr
    table = done.stdout
    header = "| step | wall s | min–max s | CPU s | lines/s | peak MB | × ast.parse | × flake8 | result |"
    assert header in table
    for label in ("ast.parse, all files", "pyflakes (subprocess)", "flake8 -j1 without plugin",
                  "flake8 -j1 + plugin, cold", "flake8 -j1 + plugin, warm",
                  "flake8 -j1 + plugin, one file changed",
                  "flake8 -j1 + plugin, topic renamed in a leaf module",
                  "pre-commit: flake8 without plugin on the edited file",
                  "pre-commit: flake8 + plugin on the edited file", "flake8 --jobs=auto without plugin",
                  "flake8 --jobs=auto + plugin, cold", "graph command", "ros2inspector graph comms"):
        assert f"| {label}" in table, label
    lines = sum(len(data.splitlines()) for data in files.values())
    assert f"— 3 files, {lines} lines;" in table
    assert "| flake8 + plugin cold ÷ flake8 without |" in table
    assert "| --jobs=auto cold ÷ --jobs=auto without (wall) |" in table
    assert "| topic renamed in a leaf module ÷ flake8 without |" in table
    assert "| pre-commit on the edited file (wall s) |" in table
    assert "| graph command ÷ ros2inspector graph (peer) |" in table
    assert "| graph command --jobs 1 ÷ ros2inspector graph (peer) |" in table
    assert re.search(r"^\d{4}-\d\d-\d\d \d\d:\d\d UTC; machine: ", table, re.MULTILINE)

    data = json.loads(out.read_text())
    steps = data["workspace"]["steps"]
    assert list(steps) == ["startup", "ast", "pyflakes", "flake8", "cold", "warm", "changed", "renamed",
                           "precommit-without", "precommit", "flake8-auto", "cold-auto", "graph", "graph-1", "peer-graph"]
    assert steps["renamed"]["result"].endswith("misspelt 'chatter' in src/chat/chat/listener.py:9")
    assert steps["graph"]["result"] == steps["graph-1"]["result"] == "2 nodes, 0 diagnostics"
    assert steps["peer-graph"]["result"] == "3 nodes and topics, 1 edges"
    # The subscription to 'unheard' has no publisher: the plugin ran and reported in every plugin row,
    # and the baseline did not.
    ros_reported = {key: int(re.search(r"(\d+) ROS", step["result"]).group(1))
                    for key, step in steps.items()
                    if key not in ("startup", "ast", "pyflakes", "graph", "graph-1", "peer-graph")}
    assert ros_reported["flake8"] == ros_reported["flake8-auto"] == 0
    assert ros_reported["cold"] > 0
    assert ros_reported["cold"] == ros_reported["warm"] == ros_reported["changed"] == ros_reported["cold-auto"]
    # The misspelt subscription has no publisher, and 'chatter' no subscriber: the change shows,
    # in the whole run and in the edited file alone.
    assert ros_reported["renamed"] == ros_reported["warm"] + 2
    assert ros_reported["precommit-without"] == 0 and ros_reported["precommit"] >= 1
    assert all(step["peak_mb"] is None or step["peak_mb"] > 0 for step in steps.values())

    # The benchmark works on a copy: no cache, no edit in the measured directory.
    present = sorted(p for p in workspace.rglob("*") if p.is_file())
    assert present == sorted([*files, workspace / "src/chat/package.xml"])
    assert all(path.read_bytes() == data for path, data in files.items())


@pytest.mark.parametrize("hide, expect_plugin", [(True, False), (False, True)])
def test_launcher_hides_the_plugin_from_flake8(hide: bool, expect_plugin: bool) -> None:
    args = ["--hide", "flake8-rosgraph"] if hide else []
    done = subprocess.run([sys.executable, str(BENCH_DIR / "flake8_launcher.py"), *args, "--", "--version"],
                          capture_output=True, text=True, timeout=120, check=True)
    assert ("flake8-rosgraph" in done.stdout) is expect_plugin
    assert "pycodestyle" in done.stdout and "pyflakes" in done.stdout


def test_synthetic_workspace_is_deterministic_valid_python(tmp_path: Path) -> None:
    first = synth.write_workspace(tmp_path / "a", 2)
    second = synth.write_workspace(tmp_path / "b", 2)
    files = sorted(p.relative_to(first) for p in first.rglob("*") if p.is_file())
    assert files == sorted(p.relative_to(second) for p in second.rglob("*") if p.is_file())
    assert all((first / f).read_bytes() == (second / f).read_bytes() for f in files)

    sources = [first / f for f in files if f.suffix == ".py"]
    lines = sum(len(p.read_text().splitlines()) for p in sources)
    assert 2 * 5500 < lines < 2 * 7000  # one fleet is sized so that 16 fleets are about 100,000 lines
    warnings = []
    for path in sources:
        ast.parse(path.read_text(), str(path))

        class Collect(Reporter):
            def flake(self, message: object) -> None:
                warnings.append(str(message))

        pyflakes_check(path.read_text(), str(path), Collect(None, None))
    assert warnings == []


def test_synthetic_graph_grows_with_the_scale(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(synth, "CHANNELS_PER_FLEET", 2)  # same code shapes, quick to analyse
    one = build_graph(synth.write_workspace(tmp_path / "one", 1))
    two = build_graph(synth.write_workspace(tmp_path / "two", 2))
    names_one = {n.fqn for n in one.nodes}
    names_two = {n.fqn for n in two.nodes}
    # 2 drivers + 2 filters + controller + mission + console, per fleet, each in its own namespace.
    expected = ("range0_driver", "imu1_driver", "range0_filter", "imu1_filter", "controller", "mission",
                "console")
    assert names_one == {f"/fleet01/{name}" for name in expected}
    assert names_two == names_one | {n.replace("/fleet01/", "/fleet02/") for n in names_one}
    topics_two = {e.name for _, e in two.entities("publishers")}
    assert "/fleet02/sensors/imu1/filtered" in topics_two and "/fleet01/sensors/imu1/filtered" in topics_two


def test_loglog_fit_recovers_the_exponent() -> None:
    sizes = [1000, 2000, 4000, 8000, 16000]
    assert growth.loglog_exponent(sizes, [3e-5 * s ** 1.5 for s in sizes]) == pytest.approx(1.5)
    assert growth.loglog_exponent(sizes, [0.2 * s for s in sizes]) == pytest.approx(1.0)
    assert growth.loglog_exponent([1000], [1.0]) is None


def test_readme_block_is_replaced_with_what_the_run_printed() -> None:
    import report
    readme = f"# Speed\n\nintro\n\n{report.README_BEGIN}\nold tables\n{report.README_END}\n\n## History\n"
    updated = report.with_readme_block(readme, "2026-11-27 UTC; machine: …\n\n| step |\n", "benchmarks/run.py ws")
    assert updated.startswith("# Speed\n\nintro\n\n" + report.README_BEGIN + "\nPrinted by `benchmarks/run.py ws`")
    assert "```\n2026-11-27 UTC; machine: …\n\n| step |\n```\n" + report.README_END in updated
    assert "old tables" not in updated and updated.endswith("## History\n")
    with pytest.raises(ValueError):
        report.with_readme_block("no block here", "x", "y")
