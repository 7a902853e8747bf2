"""A generated workspace of many cooperating nodes, for views that must stay usable at scale.

Ten ``ament_python`` packages of fifteen nodes each, shaped like a robot's
stack: each package is a pipeline of five stages with three parallel branches
(each node subscribes to the previous stage of its branch); the first package
(perception) reads the raw sensor topics and every other package's first
stage reads perception's output, so the data flow is wide and shallow.
Every fifth node serves a reset service; every other package calls perception's. Each package has a
launch file starting its executable in a namespace.
"""
from __future__ import annotations

from pathlib import Path

PACKAGES = ("perception", "localization", "mapping", "planning", "control",
            "safety", "telemetry", "docking", "arm", "gripper")
STAGES = 5
BRANCHES = 3
NODES_PER_PACKAGE = STAGES * BRANCHES

_SETUP = """from setuptools import setup

package_name = '{pkg}'
setup(
    name=package_name,
    packages=[package_name],
    entry_points={{'console_scripts': ['{pkg}_main = {pkg}.nodes:main']}},
)
"""

_PACKAGE_XML = """<?xml version="1.0"?>
<package format="3">
  <name>{pkg}</name>
  <version>0.1.0</version>
  <description>generated</description>
  <maintainer email="dev@example.com">dev</maintainer>
  <license>Apache-2.0</license>
  <export><build_type>ament_python</build_type></export>
</package>
"""

_LAUNCH = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='{pkg}', executable='{pkg}_main', namespace='{pkg}_ns'),
    ])
"""


def _topic(pkg: str, stage: int, branch: int) -> str:
    return f"/{pkg}/s{stage}_b{branch}"


def _node_class(pkg: str, index: int, previous_topic: str) -> str:
    name = f"{pkg}_stage{index}"
    lines = [
        f"class Stage{index}(Node):",
        "    def __init__(self):",
        f"        super().__init__('{name}')",
        f"        self.pub = self.create_publisher(String, '{_topic(pkg, index // BRANCHES, index % BRANCHES)}', 10)",
        f"        self.sub = self.create_subscription(String, '{previous_topic}', self.on_msg, 10)",
    ]
    if index % 5 == 0:
        lines.append(f"        self.srv = self.create_service(Trigger, '/{pkg}/reset{index}', self.on_reset)")
    lines += [
        "",
        "    def on_msg(self, msg):",
        "        self.pub.publish(msg)",
    ]
    if index % 5 == 0:
        lines += ["", "    def on_reset(self, request, response):", "        return response"]
    return "\n".join(lines)


def write_fleet(root: Path) -> int:
    """Write the workspace under ``root``; return the number of nodes it creates."""
    for p, pkg in enumerate(PACKAGES):
        folder = root / "src" / pkg
        (folder / pkg).mkdir(parents=True)
        (folder / "launch").mkdir()
        (folder / "package.xml").write_text(_PACKAGE_XML.format(pkg=pkg))
        (folder / "setup.py").write_text(_SETUP.format(pkg=pkg))
        (folder / "launch" / f"{pkg}.launch.py").write_text(_LAUNCH.format(pkg=pkg))
        (folder / pkg / "__init__.py").write_text("")
        classes = []
        for i in range(NODES_PER_PACKAGE):
            stage, branch = divmod(i, BRANCHES)
            if stage:
                before = _topic(pkg, stage - 1, branch)
            else:
                before = _topic(PACKAGES[0], STAGES - 1, branch) if p else f"/sensors/raw{branch}"
            classes.append(_node_class(pkg, i, before))
        client = (f"        helper.create_client(Trigger, '/{PACKAGES[0]}/reset0')\n" if p else "")
        main = (
            "def main():\n"
            "    rclpy.init()\n"
            f"    nodes = [{', '.join(f'Stage{i}()' for i in range(NODES_PER_PACKAGE))}]\n"
            "    helper = nodes[0]\n"
            f"{client.replace('        ', '    ')}"
            "    executor = MultiThreadedExecutor()\n"
            "    for node in nodes:\n"
            "        executor.add_node(node)\n"
            "    executor.spin()\n"
        )
        source = ("import rclpy\nfrom rclpy.executors import MultiThreadedExecutor\nfrom rclpy.node import Node\n"
                  "from std_msgs.msg import String\nfrom std_srvs.srv import Trigger\n\n\n"
                  + "\n\n\n".join(classes) + "\n\n\n" + main)
        (folder / pkg / "nodes.py").write_text(source)
    return len(PACKAGES) * NODES_PER_PACKAGE
