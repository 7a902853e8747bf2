"""ROS201 unknown-executable."""
from __future__ import annotations

from typing import Iterator

from ..graph import names
from ..graph.model import RosGraph
from .base import Finding, Rule, RuleConfig


class UnknownExecutable(Rule):
    """## What it does
    Checks that every node a launch file (Python, XML or YAML) starts names
    an executable its package really installs: a `console_scripts` entry of
    an `ament_python` package (`setup.py` or `setup.cfg`), or an
    `add_executable` target / `install(PROGRAMS …)` script of an
    `ament_cmake` package.

    ## Why is this bad?
    `ros2 launch` fails with "executable '…' not found on the libexec
    directory" and the whole system does not come up — typically after a
    rename in `setup.py` that the launch file did not follow.

    ## Known problems
    Only packages that are in the analysed workspace are judged: an
    installed package (`robot_state_publisher`) is not. A package whose
    executables cannot all be read statically (an entry point built at run
    time, a CMake variable in a target name) is not judged either. A launch
    file that another launch file of the workspace includes is judged as
    included, with the arguments its includers pass, not alone with its
    placeholder defaults (`LaunchConfiguration('sensor', default='sensor_default')`).

    ## Example
    ```python
    Node(package='demo_py', executable='talkr')
    ```

    ## Use instead
    ```python
    Node(package='demo_py', executable='talker')
    ```

    ## Options
    None.
    """

    code = "ROS201"
    name = "unknown-executable"
    level = "error"
    precision = "very-high"  # SARIF/code-scanning precision: how often a finding is a real problem
    summary = ("a launch file starts a package/executable that the workspace holds no such entry for "
               "(only for packages that are in the workspace)")

    def check(self, graph: RosGraph, config: RuleConfig) -> Iterator[Finding]:
        included = {path for system in graph.systems for path in system.files[1:]}
        for system in graph.systems:
            for node in system.nodes:
                if node.target.status != "missing-executable":
                    continue
                if system.launch_file in included and node.location.path == system.launch_file:
                    continue  # judged where it is included, with the values passed to it
                message = f"package '{node.package}' has no executable '{node.executable}'"
                close = sorted(k for k in node.target.known
                               if names.edit_distance(k, node.executable or "", 2) <= 2)
                if close:
                    message += f"; did you mean '{close[0]}'?"
                elif node.target.known:
                    message += f" (it has: {', '.join(node.target.known)})"
                yield Finding(node.location, self.code, message)
