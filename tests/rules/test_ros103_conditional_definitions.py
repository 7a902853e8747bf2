"""ROS103 on a callback whose name is defined twice under a condition.

Bridges that run on ROS 1 and ROS 2 define their callbacks per version::

    if ROS_VERSION == 1:
        def on_params(self, config, level): ...
    else:
        def on_params(self, params): ...

The name holds one function or the other, so a registration is wrong only if every
definition is. Both definitions share a qualified name; the usage facts once kept whichever
the hash seed put first, so the finding came and went between runs of the same code.
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

NODE = """\
import os

import rclpy
from rclpy.node import Node
from rcl_interfaces.msg import SetParametersResult

ROS_VERSION = int(os.environ.get('ROS_VERSION', 0))


class Bridge(Node):
    def __init__(self):
        super().__init__('bridge')
        self.add_on_set_parameters_callback(self.on_params)
        self.create_timer(1.0, self.on_tick)

    if ROS_VERSION == 1:
        def on_params(self, config, level):
            return config

        def on_tick(self, event):
            pass
    else:
        def on_params(self, params):
            return SetParametersResult(successful=True)

        def on_tick(self, {tick_parameters}):
            pass


def main():
    rclpy.init()
    rclpy.spin(Bridge())
"""

SETUP = """\
from setuptools import setup
setup(name='bridge', packages=['bridge'], entry_points={'console_scripts': ['bridge = bridge.node:main']})
"""


def _check(root: Path, seed: str, cache: Path) -> list[tuple[str, int, str]]:
    env = {k: v for k, v in os.environ.items() if not k.startswith("ROSGRAPH_")}
    env.update(PYTHONHASHSEED=seed, ROSGRAPH_CACHE_DIR=str(cache / seed))
    done = subprocess.run([sys.executable, "-m", "flake8_rosgraph", "check", ".", "--format", "json",
                           "--select", "ROS103"], cwd=root, env=env, capture_output=True, text=True,
                          timeout=300, check=False)
    assert done.returncode in (0, 1), done.stderr
    return [(f["path"], f["line"], f["code"]) for f in json.loads(done.stdout)["findings"]]


@pytest.mark.parametrize("tick_parameters, expected", [
    ("event=None", []),                                       # the ROS 2 definitions fit
    ("event", [("bridge/bridge/node.py", 14, "ROS103")]),     # neither on_tick fits a timer
])
def test_a_registration_is_wrong_only_if_every_definition_is(tmp_path: Path, tick_parameters: str,
                                                             expected: list) -> None:
    root = tmp_path / "ws"
    (root / "bridge/bridge").mkdir(parents=True)
    (root / "bridge/package.xml").write_text("<package format=\"3\"><name>bridge</name></package>\n")
    (root / "bridge/setup.py").write_text(SETUP)
    (root / "bridge/bridge/__init__.py").write_text("")
    (root / "bridge/bridge/node.py").write_text(NODE.format(tick_parameters=tick_parameters))
    runs = {seed: _check(root, seed, tmp_path / "cache") for seed in ("1", "2", "3", "6", "7")}
    assert all(found == expected for found in runs.values()), runs
