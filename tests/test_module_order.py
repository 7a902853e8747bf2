"""A module runs before its names are read, as ``import`` runs it in Python.

A module that imports names from a sibling module that sorts after it (``app`` reading
``topics``) used to run with those names still ⊥, and again (with everything it called) once
the sibling had run. Calls made on values that were still growing spent contexts of the
helpers they called on values that never occur at run time. Now the sibling runs on the
spot, and in an import chain without cycles every task runs once.
"""
from __future__ import annotations

from flake8_rosgraph.analysis import analyse

from test_workspace_discovery import write

JOINTS = ("shoulder_pan", "shoulder_lift", "elbow", "wrist_1", "wrist_2", "wrist_3", "gripper", "camera_tilt")

SETUP = """
    from setuptools import setup
    setup(name='arm_bringup', packages=['arm_bringup'],
          entry_points={'console_scripts': ['arm = arm_bringup.app:main']})
"""

APP = """
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import Float64

    from arm_bringup.{module} import {names}


    class ArmCommander(Node):
        def __init__(self):
            super().__init__('arm_commander')
            self.commands = [{calls}]

        def _command(self, joint):
            return self.create_publisher(Float64, joint + '/command', 10)


    def main():
        rclpy.init()
        rclpy.spin(ArmCommander())


    if __name__ == '__main__':
        main()
"""


def _arm(tmp_path, module: str):
    constants = "".join(f"{j.upper()} = '{j}'\n" for j in JOINTS)
    return write(tmp_path, {
        "src/arm_bringup/package.xml": "<package format='3'><name>arm_bringup</name></package>\n",
        "src/arm_bringup/setup.py": SETUP,
        "src/arm_bringup/arm_bringup/__init__.py": "",
        f"src/arm_bringup/arm_bringup/{module}.py": constants,
        "src/arm_bringup/arm_bringup/app.py": APP.format(
            module=module, names=", ".join(j.upper() for j in JOINTS),
            calls=", ".join(f"self._command({j.upper()})" for j in JOINTS)),
    })


def _published(root):
    graph, analyses = analyse(root)
    names = sorted(e.name or "?" for n in graph.nodes for e in n.entities if e.kind == "publishers")
    bounded = [d.message for d in graph.diagnostics if "different ways" in d.message]
    runs = sum(a.task_runs for a in analyses)
    tasks = sum(len(a.effects) for a in analyses)  # every task that ran, once each
    return names, bounded, runs, tasks


def test_a_module_whose_names_are_imported_runs_first_whatever_the_file_names(tmp_path):
    for module in ("topics", "a_topics"):  # sorts after ``app``, and before it
        names, bounded, runs, tasks = _published(_arm(tmp_path / module, module))
        assert names == sorted(f"/{j}/command" for j in JOINTS)
        assert bounded == []
        assert runs == tasks  # no task ran twice
