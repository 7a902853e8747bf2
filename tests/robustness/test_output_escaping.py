"""Names from the analysed code cannot forge output lines or drive the terminal.

A topic literal holding a newline and a fake ``path:line:col: F401`` line, or an
ANSI escape, reaches the message of a finding. Text, JSON and SARIF output and
flake8's own output must show it escaped; and the string-formatting model must
never evaluate attribute access or indexing on the analyser's own objects.
"""
from __future__ import annotations

import json
import re
import sys
from pathlib import Path

import pytest

from flake8_rosgraph.escaping import escape_text, json_safe

from .harness import clean_env, flake8_executable, run
from .metadata_workspace import CHAT, TIGHT_MEMORY, write_workspace

FORGING_NODE = '''\
import rclpy
from rclpy.node import Node
from std_msgs.msg import String

FORGED = 'status\\nsrc/chat_pkg/chat_pkg/talker.py:1:1: F401 forged'


class Forger(Node):
    def __init__(self):
        super().__init__('forger')
        self.pub = self.create_publisher(String, FORGED, 10)
        self.sub = self.create_subscription(String, 'alarm\\x1b[2K\\x1b[31m', self.on_alarm, 10)
        self.ok = self.create_subscription(String, 'chatter', self.on_alarm, 10)

    def on_alarm(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(Forger())
'''

FORMAT_NODE = '''\
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Formatter(Node):
    def __init__(self):
        super().__init__('formatter')
        self.a = self.create_subscription(String, '{0.__class__}'.format(''), self.cb, 10)
        self.b = self.create_subscription(String, 'x{0.__add__}'.format(''), self.cb, 10)
        self.c = self.create_subscription(String, 'y{0[0]}'.format('abc'), self.cb, 10)
        self.d = self.create_publisher(String, 'plain_{}'.format('topic'), 10)

    def cb(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(Formatter())
'''

FORGED_LINE = re.compile(r"^src/chat_pkg/chat_pkg/talker\.py:1:1: F401", re.MULTILINE)


@pytest.fixture
def ws(tmp_path: Path) -> Path:
    root = write_workspace(tmp_path / "ws")
    (root / CHAT / "chat_pkg" / "forger.py").write_text(FORGING_NODE)
    return root


def _tool(*args: str, cwd: Path):
    done = run([sys.executable, "-m", "flake8_rosgraph", *args], cwd, clean_env(), memory_cap=TIGHT_MEMORY,
               hang_guard=60)
    assert done is not None and "Traceback" not in done.stderr, done and done.explain()
    return done


def _assert_safe(text: str) -> None:
    assert not FORGED_LINE.search(text), text
    assert "\x1b" not in text, text


def test_text_output_escapes_names(ws: Path) -> None:
    done = _tool("check", str(ws), cwd=ws)
    assert done.returncode == 1
    _assert_safe(done.stdout)
    assert "status\\x0asrc/chat_pkg" in done.stdout, done.stdout
    assert "alarm\\x1b[2K" in done.stdout, done.stdout


def test_json_and_sarif_output_escape_names(ws: Path, tmp_path: Path) -> None:
    sarif = tmp_path / "out.sarif"
    done = _tool("check", str(ws), "--format=json", f"--sarif={sarif}", cwd=ws)
    log = sarif.read_text(encoding="utf-8")
    for text in (done.stdout, log):
        _assert_safe(text)
    messages = [f["message"] for f in json.loads(done.stdout)["findings"]]
    messages += [r["message"]["text"] for run_ in json.loads(log)["runs"] for r in run_["results"]]
    assert len(messages) >= 4 and not any("\n" in m or "\x1b" in m for m in messages), messages
    graph = _tool("graph", str(ws), cwd=ws)
    _assert_safe(graph.stdout)
    assert json.loads(graph.stdout)  # still valid JSON


def test_flake8_output_escapes_names(ws: Path) -> None:
    done = run([flake8_executable(), "--isolated", "--select", "ROS", str(ws)], ws, clean_env(),
               memory_cap=TIGHT_MEMORY, hang_guard=60)
    assert done is not None and done.returncode == 1, done and done.explain()
    assert not re.search(r"^\S*talker\.py:1:1: F401", done.stdout, re.MULTILINE), done.stdout
    assert "\x1b" not in done.stdout


def test_format_never_reads_attributes_of_real_objects(ws: Path) -> None:
    (ws / CHAT / "chat_pkg" / "formatter.py").write_text(FORMAT_NODE)
    outputs = set()
    for seed in ("0", "1", "2"):
        env = clean_env(PYTHONHASHSEED=seed)
        done = run([sys.executable, "-m", "flake8_rosgraph", "graph", str(ws)], ws, env, hang_guard=60)
        assert done is not None and done.returncode == 0, done and done.explain()
        outputs.add(done.stdout)
    assert len(outputs) == 1, "output depends on the process"
    graph = json.loads(outputs.pop())
    topics = {e["topic"] for n in graph["nodes"] if n["name"] == "formatter"
              for kind in ("publishers", "subscriptions") for e in n[kind]}
    assert "/plain_topic" in topics
    assert not any(t and ("class" in t or "0x" in t or "wrapper" in t or t.startswith("/ya")) for t in topics), topics


@pytest.mark.parametrize("raw, shown", [
    ("a\nb", "a\\x0ab"), ("\x1b[31m", "\\x1b[31m"), ("\u202eevil", "\\u202eevil"), ("caf\udce9", "caf\\udce9"),
    ("plain/topic", "plain/topic"), ("back\\slash", "back\\slash"), ("\x9b2J", "\\x9b2J"),
])
def test_escape_text(raw: str, shown: str) -> None:
    assert escape_text(raw) == shown
    assert escape_text(shown) == shown  # idempotent: escaping twice shows the same


def test_json_safe_keeps_the_data() -> None:
    data = {"name": "x\x85y\u2028z\u202e\x9b", "ok": "caf\u00e9"}
    text = json_safe(json.dumps(data, ensure_ascii=False))
    assert json.loads(text) == data
    assert not re.search("[\x7f-\x9f\u2028\u202e]", text) and "caf\u00e9" in text
