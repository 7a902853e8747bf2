"""Findings a read of every finding on 18 further public repositories (a simulator bridge, a
scenario runner, robot bring-ups, drivers, LLM and HRI nodes) found false, each fixed by a
general mechanism: a realistic multi-file workspace with the pattern that was misjudged, and a
near-identical twin holding the real bug, which must still be reported."""
from __future__ import annotations

from pathlib import Path

from test_recall_mechanisms import findings
from test_workspace_discovery import PACKAGE_XML, setup_py, write


# -- one call of one of two tree classes declares a parameter once ----------------------------------
TREES = """
    class PlainTree:
        def setup(self, node):
            node.declare_parameter('tick_period', 0.1)


    class LoggingTree(PlainTree):
        def setup(self, node):
            node.declare_parameter('tick_period', 0.1)
            node.declare_parameter('log_level', 'info')
"""

RUNNER = """
    import sys

    import rclpy
    from rclpy.node import Node

    from runner.trees import LoggingTree, PlainTree


    class Runner(Node):
        def __init__(self, verbose):
            super().__init__('runner')
            self.tree = LoggingTree() if verbose else PlainTree()
            {setup}


    def main():
        rclpy.init()
        rclpy.spin(Runner('-v' in sys.argv))
"""


def runner_workspace(root: Path, setup: str) -> Path:
    return write(root, {
        "runner/package.xml": PACKAGE_XML.format(name="runner", build="ament_python"),
        "runner/setup.py": setup_py("runner", "'runner = runner.main:main'"),
        "runner/runner/__init__.py": "",
        "runner/runner/trees.py": TREES,
        "runner/runner/main.py": RUNNER.format(setup=setup),
    })


def test_one_call_of_one_of_two_classes_declares_once(tmp_path: Path) -> None:
    """scenario_execution: ``self.behaviour_tree.setup(...)`` reaches one of the tree classes'
    ``setup``; both declare ``default_snapshot_stream``, and the two callees of one call were
    counted as two calls in a row ("declared again", first declared at the same place)."""
    root = runner_workspace(tmp_path, "self.tree.setup(self)")
    assert findings(root, ["ROS102"]) == []


def test_the_tree_set_up_twice_still_declares_again(tmp_path: Path) -> None:
    """The twin: two calls in a row declare the names twice."""
    root = runner_workspace(tmp_path, "self.tree.setup(self)\n            self.tree.setup(self)")
    reported = findings(root, ["ROS102"])
    assert [(code, path, line) for code, path, line, _ in reported] == [
        ("ROS102", "runner/runner/main.py", 14)]
    assert "is declared again on node '/runner'" in reported[0][3]
