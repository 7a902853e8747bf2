"""The findings README shows under "What it finds" are what the tool prints on the workspace
in ``tests/readme_workspace`` (three packages: a driver, a bridge with a typo and a blocking
service call, a teleop with sensor-data QoS), through real flake8, line for line."""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
WORKSPACE = Path(__file__).resolve().parent / "readme_workspace"


def _readme_block() -> list[str]:
    text = (REPO / "README.md").read_text(encoding="utf-8")
    section = text.split("## What it finds", 1)[1]
    block = re.search(r"```console\n\$ (?P<command>[^\n]+)\n(?P<output>.*?)```", section, re.S)
    assert block is not None, "README's What it finds has a console block"
    assert block["command"] == "flake8 --select ROS src/"
    return block["output"].splitlines()


def test_readme_findings_are_the_tools_output(tmp_path: Path) -> None:
    root = tmp_path / "ws"
    shutil.copytree(WORKSPACE, root)
    (root / ".git").mkdir()  # a workspace of its own, as a clone is
    env = {k: v for k, v in os.environ.items() if not k.startswith("ROSGRAPH_")}
    done = subprocess.run([sys.executable, "-m", "flake8", "--isolated", "--select", "ROS", "src/"],
                          cwd=root, capture_output=True, text=True, timeout=300, env=env)
    assert done.returncode == 1, done.stderr
    # flake8 4.0.1 prints files in the order its checkers finish; README lists them sorted
    assert sorted(done.stdout.splitlines()) == _readme_block() == sorted(_readme_block())
