"""A small colcon workspace with launch files, parameter files and two packages, for hostile-metadata tests.

The workspace has one known launch bug and its near-identical correct twin:
``bringup.launch.xml`` starts ``chat_pkg``'s ``talkr`` (a typo of ``talker``:
ROS201) and its ``listener`` (correct, quiet). Whatever hostile file a test
adds elsewhere, that ROS201 must still be reported — the proof that one bad
input did not cost the other launch systems — and the listener must stay quiet.
"""
from __future__ import annotations

import json
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Mapping

from .harness import Run, clean_env, run

PACKAGE_XML = """\
<?xml version="1.0"?>
<package format="3">
  <name>{name}</name>
  <version>0.1.0</version>
  <description>{name}</description>
  <maintainer email="dev@example.com">dev</maintainer>
  <license>Apache-2.0</license>
  <export>
    <build_type>{build_type}</build_type>
  </export>
</package>
"""

SETUP_PY = """\
from setuptools import setup

package_name = 'chat_pkg'

setup(
    name=package_name,
    packages=[package_name],
    entry_points={
        'console_scripts': [
            'talker = ' + package_name + '.talker:main',
            'listener = chat_pkg.listener:main',
        ],
    },
)
"""

TALKER = """\
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Talker(Node):
    def __init__(self):
        super().__init__('talker')
        self.pub = self.create_publisher(String, 'chatter', 10)
        self.timer = self.create_timer(0.5, self.tick)

    def tick(self):
        self.pub.publish(String(data='hi'))


def main():
    rclpy.init()
    rclpy.spin(Talker())
"""

LISTENER = """\
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Listener(Node):
    def __init__(self):
        super().__init__('listener')
        self.declare_parameter('rate', 1.0)
        self.sub = self.create_subscription(String, 'chatter', self.on_msg, 10)

    def on_msg(self, msg):
        self.get_logger().info(msg.data)


def main():
    rclpy.init()
    rclpy.spin(Listener())
"""

BRINGUP = """\
<launch>
  <node pkg="chat_pkg" exec="talkr" name="talker"/>
  <node pkg="chat_pkg" exec="listener" name="listener">
    <param from="$(find-pkg-share chat_pkg)/config/listener.yaml"/>
  </node>
</launch>
"""

PARAMS = """\
listener:
  ros__parameters:
    rate: 2.0
"""

CMAKE = """\
cmake_minimum_required(VERSION 3.8)
project(drive_pkg)
find_package(ament_cmake REQUIRED)
add_executable(driver src/driver.cpp)
install(TARGETS driver DESTINATION lib/${PROJECT_NAME})
ament_package()
"""

#: Where the typo is: the path and line of the ROS201 every run must still report.
TYPO = ("src/chat_pkg/launch/bringup.launch.xml", 2)
CHAT = "src/chat_pkg"


def write_workspace(root: Path) -> Path:
    """Write the workspace under ``root`` (``root/src/…``) and return ``root``."""
    files = {
        f"{CHAT}/package.xml": PACKAGE_XML.format(name="chat_pkg", build_type="ament_python"),
        f"{CHAT}/setup.py": SETUP_PY,
        f"{CHAT}/chat_pkg/__init__.py": "",
        f"{CHAT}/chat_pkg/talker.py": TALKER,
        f"{CHAT}/chat_pkg/listener.py": LISTENER,
        f"{CHAT}/launch/bringup.launch.xml": BRINGUP,
        f"{CHAT}/config/listener.yaml": PARAMS,
        "src/drive_pkg/package.xml": PACKAGE_XML.format(name="drive_pkg", build_type="ament_cmake"),
        "src/drive_pkg/CMakeLists.txt": CMAKE,
        "src/drive_pkg/src/driver.cpp": "int main() { return 0; }\n",
    }
    for rel, text in files.items():
        path = root / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text, encoding="utf-8")
    return root


@dataclass(frozen=True)
class Checked:
    """A ``check --format json`` run and what it reported."""

    done: Run
    report: Mapping[str, Any]

    @property
    def findings(self) -> set[tuple[str, str, int]]:
        return {(f["code"], f["path"], f["line"]) for f in self.report["findings"]}

    def diagnostics_on(self, path: str) -> list[str]:
        return [d["message"] for d in self.report["diagnostics"] if d["path"] == path]

    def assert_launch_survived(self) -> None:
        """The typo's ROS201 is still reported: the other launch systems were not lost."""
        assert ("ROS201",) + TYPO in self.findings, self.done.explain()


#: Address-space cap of one hostile run: a few hundred MiB is what the analysis of this
#: workspace needs; the attacks in the issue took 1–5 GiB.
TIGHT_MEMORY = 1536 * 1024 ** 2
#: A run of this small workspace takes one to three seconds; this only separates a hang.
TIGHT_GUARD_S = 60


def check(root: Path, *options: str, cwd: Path | None = None, env: Mapping[str, str] | None = None,
          allowed: tuple[int, ...] = (1,)) -> Checked:
    """``flake8-rosgraph check ROOT --format json`` under the tight memory cap and hang guard."""
    done = run([sys.executable, "-m", "flake8_rosgraph", "check", str(root), "--format", "json",
                "--cache-dir", str(root.parent / "cache"), *options],
               cwd or root, env if env is not None else clean_env(),
               memory_cap=TIGHT_MEMORY, hang_guard=TIGHT_GUARD_S)
    assert done is not None
    assert done.returncode in allowed, done.explain()
    assert "Traceback" not in done.stderr, done.explain()
    report = json.loads(done.stdout) if done.stdout.strip() else {"findings": [], "diagnostics": []}
    return Checked(done, report)


def graph_messages(root: Path, env: Mapping[str, str] | None = None) -> dict[str, list[str]]:
    """``graph ROOT`` under the same caps: every diagnostic and launch-system problem, by path."""
    done = run([sys.executable, "-m", "flake8_rosgraph", "graph", str(root)], root,
               env if env is not None else clean_env(), memory_cap=TIGHT_MEMORY, hang_guard=TIGHT_GUARD_S)
    assert done is not None and done.returncode == 0, done and done.explain()
    graph = json.loads(done.stdout)
    out: dict[str, list[str]] = {}
    problems = [p for system in graph.get("systems", ()) for p in system["problems"]]
    unresolved = [{"path": node["file"], "message": reason} for system in graph.get("systems", ())
                  for node in system["nodes"] for reason in node.get("unresolved", ())]
    for item in [*graph["diagnostics"], *problems, *unresolved]:
        out.setdefault(item["path"], []).append(item["message"])
    return out
