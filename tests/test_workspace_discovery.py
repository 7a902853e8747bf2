"""Which files are Python nodes and what Python would import them as.

Real packages ship nodes as extension-less executables (a Python shebang, setup.py
``scripts=``, CMake ``install(PROGRAMS …)``) and keep stray ``__init__.py`` files at the ROS
package root or in ``src/``; neither may cost the nodes or the imports between modules.
"""
from __future__ import annotations

import textwrap
from pathlib import Path

from flake8_rosgraph.analysis import build_graph
from flake8_rosgraph.workspace import load_workspace

PACKAGE_XML = """<?xml version="1.0"?>
<package format="3"><name>{name}</name><version>0.1.0</version><description>d</description>
<maintainer email="a@b.c">a</maintainer><license>MIT</license>
<exec_depend>rclpy</exec_depend><export><build_type>{build}</build_type></export></package>
"""

def setup_py(name: str, scripts: str) -> str:
    """An ament_python package's ``setup.py`` (indented, as :func:`write` takes it) with these
    ``console_scripts`` entries (``"'exe = pkg.module:main'"``, comma-separated)."""
    return f"""
        from setuptools import find_packages, setup

        setup(
            name='{name}',
            packages=find_packages(exclude=['test']),
            entry_points={{'console_scripts': [{scripts}]}},
        )
    """


BASE = """
    from rclpy.node import Node
    from std_msgs.msg import String


    class Pattern(Node):
        def __init__(self, name):
            super().__init__(name)
            self.cmd = self.create_publisher(String, 'cmd_out', 10)
"""


def write(root: Path, files: dict[str, str]) -> Path:
    for rel, text in files.items():
        path = root / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(textwrap.dedent(text).lstrip("\n"), encoding="utf-8")
    return root


def topics(root: Path) -> dict[str, list[str]]:
    graph = build_graph(root)
    return {node.fqn: sorted(e.name or "?" for e in node.entities if e.kind == "publishers")
            for node in graph.nodes}


def names(root: Path) -> dict[str, str]:
    return {m.path: m.name for m in load_workspace(root).modules}


def test_stray_init_at_package_root_and_in_src_does_not_shadow_the_package(tmp_path: Path) -> None:
    root = write(tmp_path, {
        "src/__init__.py": "",
        "src/swarm/__init__.py": "",
        "src/swarm/package.xml": PACKAGE_XML.format(name="swarm", build="ament_python"),
        "src/swarm/setup.py": "from setuptools import setup\nsetup(name='swarm', packages=['swarm'])\n",
        "src/swarm/swarm/__init__.py": "",
        "src/swarm/swarm/pattern.py": BASE,
        "src/swarm/swarm/movement/__init__.py": "",
        "src/swarm/swarm/movement/drive.py": """
            import rclpy
            from swarm.pattern import Pattern


            class Drive(Pattern):
                def __init__(self):
                    super().__init__('drive')


            def main():
                rclpy.init()
                rclpy.spin(Drive())
        """,
    })
    assert names(root)["src/swarm/swarm/movement/drive.py"] == "swarm.movement.drive"
    assert topics(root) == {"/drive": ["/cmd_out"]}


def test_src_layout_and_package_dir(tmp_path: Path) -> None:
    root = write(tmp_path, {
        "tools/package.xml": PACKAGE_XML.format(name="tools", build="ament_python"),
        "tools/setup.py": """
            from setuptools import setup
            setup(name='tools', packages=['tools'], package_dir={'': 'lib'})
        """,
        "tools/lib/__init__.py": "",
        "tools/lib/tools/__init__.py": "",
        "tools/lib/tools/pattern.py": BASE,
        "tools/lib/tools/relay.py": """
            import rclpy
            from tools.pattern import Pattern


            def main():
                rclpy.init()
                rclpy.spin(Pattern('relay'))
        """,
    })
    assert names(root)["tools/lib/tools/relay.py"] == "tools.relay"
    assert topics(root) == {"/relay": ["/cmd_out"]}


def test_package_without_markers_keeps_its_parent_packages(tmp_path: Path) -> None:
    """Precision: only distribution roots cut the name; ordinary packages stay whole."""
    root = write(tmp_path, {
        "app/__init__.py": "",
        "app/src/__init__.py": "",
        "app/src/mod.py": "X = 1\n",
    })
    assert names(root)["app/src/mod.py"] == "app.src.mod"


def test_executables_without_py_suffix_are_analysed(tmp_path: Path) -> None:
    node = """
        import rclpy
        from std_msgs.msg import String

        rclpy.init()
        node = rclpy.create_node('{name}')
        node.create_publisher(String, '{topic}', 10)
        rclpy.spin(node)
    """
    root = write(tmp_path, {
        "bridge/package.xml": PACKAGE_XML.format(name="bridge", build="ament_cmake"),
        "bridge/CMakeLists.txt": """
            cmake_minimum_required(VERSION 3.5)
            project(bridge)
            install(PROGRAMS
              scripts/republisher
              DESTINATION lib/${PROJECT_NAME})
        """,
        "bridge/scripts/republisher": node.format(name="republisher", topic="out"),
        "bridge/scripts/shebang_node": "#!/usr/bin/env python3\n" + textwrap.dedent(
            node.format(name="shebang_node", topic="shebang")),
        "legacy/setup.py": """
            from setuptools import setup
            setup(name='legacy', scripts=['bin/legacy_node'])
        """,
        "legacy/bin/legacy_node": node.format(name="legacy_node", topic="legacy"),
        # Not Python: a shell script, and a data file without suffix: never read as code.
        "bridge/scripts/run.sh": "#!/bin/bash\necho create_node\n",
        "bridge/scripts/start": "#!/bin/sh\nexec ros2 run bridge republisher\n",
        "bridge/config/LICENSE": "create_publisher(String, 'not_code', 10)\n",
    })
    assert topics(root) == {"/legacy_node": ["/legacy"], "/republisher": ["/out"],
                            "/shebang_node": ["/shebang"]}
    assert not any("syntax error" in d.message for d in build_graph(root).diagnostics)


def test_unknown_node_name_keeps_relative_topics(tmp_path: Path) -> None:
    """A relative name needs only the namespace; ``~/`` names need the node name too."""
    root = write(tmp_path, {
        "fleet/package.xml": PACKAGE_XML.format(name="fleet", build="ament_python"),
        "fleet/fleet/__init__.py": "",
        "fleet/fleet/agent.py": """
            import sys

            import rclpy
            from rclpy.node import Node
            from std_msgs.msg import String


            class Agent(Node):
                def __init__(self, name):
                    super().__init__(name, namespace='/fleet')
                    self.create_publisher(String, 'heartbeat', 10)
                    self.create_publisher(String, '~/status', 10)


            def main():
                rclpy.init()
                rclpy.spin(Agent(sys.argv[1]))
        """,
    })
    graph = build_graph(root)
    (node,) = graph.nodes
    assert node.name is None and node.namespace == "/fleet"
    assert sorted(e.name or "?" for e in node.entities) == ["/fleet/heartbeat", "?"]


ROS1_PACKAGE_XML = """<?xml version="1.0"?>
<package format="2"><name>{name}</name><version>0.1.0</version><description>d</description>
<maintainer email="a@b.c">a</maintainer><license>MIT</license>
<buildtool_depend{condition}>catkin</buildtool_depend><exec_depend>rospy</exec_depend></package>
"""


def test_ros1_packages_and_ignored_folders_are_left_out_and_said(tmp_path: Path) -> None:
    ws = write(tmp_path / "ws", {
        "src/legacy_driver/package.xml": ROS1_PACKAGE_XML.format(name="legacy_driver", condition=""),
        "src/legacy_driver/scripts/driver.py": "import rospy\nrospy.init_node('driver')\n",
        "src/both/package.xml": ROS1_PACKAGE_XML.format(name="both", condition=' condition="$ROS_VERSION == 1"'),
        "src/both/both/__init__.py": "",
        "src/both/both/node.py": BASE,
        "src/unsure/package.xml": ROS1_PACKAGE_XML.format(name="unsure", condition=' condition="$ROS_DISTRO == noetic"'),
        "src/unsure/unsure/node.py": BASE,
        "src/old/COLCON_IGNORE": "",
        "src/old/pattern/node.py": BASE,
    })
    workspace = load_workspace(ws)
    assert sorted(m.path for m in workspace.modules) == [
        "src/both/both/__init__.py", "src/both/both/node.py", "src/unsure/unsure/node.py"]
    said = {(d.path, d.severity): d.message for d in workspace.diagnostics}
    assert said == {
        ("src/legacy_driver/package.xml", "info"):
            "ROS 1 (catkin) package 'legacy_driver': not analysed (the rules check ROS 2 code)",
        ("src/old/COLCON_IGNORE", "info"): "COLCON_IGNORE: the build leaves this folder out; not analysed",
    }


def test_manifest_conditions_as_a_ros2_build_sees_them() -> None:
    from flake8_rosgraph.manifest import condition_holds

    assert condition_holds(None) is True
    assert condition_holds("$ROS_VERSION == 2") is True
    assert condition_holds("$ROS_VERSION == 1") is False
    assert condition_holds("$ROS_VERSION != 1 and $ROS_VERSION == 2") is True
    assert condition_holds("$ROS_VERSION == 1 or $ROS_DISTRO == humble") is None
    assert condition_holds("$ROS_VERSION == 1 and $ROS_DISTRO == humble") is False
    assert condition_holds("($ROS_VERSION == 2)") is None
