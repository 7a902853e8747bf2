"""The plugin's table of rule codes is the rules' own, and a warm flake8 run needs no more."""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from flake8_rosgraph.codes import RULE_CODES
from flake8_rosgraph.rules import RULES

#: Runs flake8 in-process, then says whether any rule module was imported.
#: One core, so that the cold run analyses in this process (with a second one a child would,
#: and this process would never import the rules either way).
_FLAKE8_THEN_PROBE = """
import os, sys
if hasattr(os, "sched_setaffinity"):
    os.sched_setaffinity(0, {min(os.sched_getaffinity(0))})
from flake8.main import cli
try:
    cli.main(["--jobs", "1", "--select", "ROS", "."])
except SystemExit:
    pass
print("rules loaded" if any(m.startswith("flake8_rosgraph.rules") for m in sys.modules) else "rules not loaded")
"""

_TALKER = """\
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Talker(Node):
    def __init__(self):
        super().__init__('talker')
        self.pub = self.create_publisher(String, 'chatter', 10)


def main():
    rclpy.init()
    rclpy.spin(Talker())
"""
_LISTENER = """\
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Listener(Node):
    def __init__(self):
        super().__init__('listener')
        self.sub = self.create_subscription(String, 'chatterr', self.on_message, 10)

    def on_message(self, msg):
        self.get_logger().info(msg.data)


def main():
    rclpy.init()
    rclpy.spin(Listener())
"""


def test_table_matches_the_rules():
    assert [(c.code, c.default_enabled) for c in RULE_CODES] == [(r.code, r.default_enabled) for r in RULES]


@pytest.mark.skipif(not hasattr(os, "sched_setaffinity"), reason="needs os.sched_setaffinity to run on one core")
def test_a_warm_run_does_not_load_the_rules(tmp_path: Path):
    """The cold run analyses (and so imports the rules); the warm one reports the kept
    findings, the same ones, without importing a rule module."""
    package = tmp_path / "src" / "talker_pkg"
    (package / "talker_pkg").mkdir(parents=True)
    (package / "package.xml").write_text("<package format='3'><name>talker_pkg</name></package>\n")
    (package / "talker_pkg" / "__init__.py").write_text("")
    (package / "talker_pkg" / "talker.py").write_text(_TALKER)
    (package / "talker_pkg" / "listener.py").write_text(_LISTENER)
    env = {**os.environ, "ROSGRAPH_ROOT": str(tmp_path), "XDG_CACHE_HOME": str(tmp_path / "xdg")}
    env.pop("ROSGRAPH_DEBUG", None)

    def flake8() -> list[str]:
        out = subprocess.run([sys.executable, "-c", _FLAKE8_THEN_PROBE], cwd=tmp_path, env=env,
                             capture_output=True, text=True, check=True, timeout=300)
        return out.stdout.splitlines()

    cold, warm = flake8(), flake8()
    assert cold[-1] == "rules loaded" and warm[-1] == "rules not loaded"
    assert any(" ROS003 " in line for line in cold), cold
    assert cold[:-1] == warm[:-1]
