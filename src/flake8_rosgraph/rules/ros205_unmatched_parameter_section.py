"""ROS205 unmatched-parameter-section."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Iterator

from ..graph import names
from ..graph.model import Location, RosGraph
from ..launch.model import LaunchedNode, System
from .base import Finding, Rule, RuleConfig


@dataclass
class _FileUse:
    """Who receives one parameter file, over every launch system that passes it."""

    sections: list = field(default_factory=list)
    fqns: set[str] = field(default_factory=set)
    passed_at: set[Location] = field(default_factory=set)
    #: Some receiving node's name or namespace is not known: any section might match it.
    open: bool = False


def _launched_fqns(system: System, launched: LaunchedNode) -> set[str] | None:
    """The fully qualified names the nodes of one launch action get; ``None`` when one is unknown."""
    if launched.is_unresolved("ros_arguments"):
        return None  # --ros-args given on the command line may rename the node
    instances = [i for i in system.instances if i.launched is launched]
    if instances:
        fqns = {i.node.fqn for i in instances}
        return None if None in fqns else fqns  # type: ignore[return-value]
    if launched.target.status == "found" or launched.name is None \
            or launched.is_unresolved("name") or launched.is_unresolved("namespace"):
        return None  # code that creates no node we know of, or a name the launch file leaves to it
    namespace = launched.namespace or "/"
    return {namespace.rstrip("/") + "/" + launched.name.lstrip("/")}


class UnmatchedParameterSection(Rule):
    """## What it does
    Checks that every node section of a parameter YAML file (`talker:`,
    `/robot1/talker:`, `/**:`, `/*/talker:`, nested namespace keys) matches
    at least one node started with that file, after the launch file's names
    and namespaces are applied, as rcl matches them.

    ## Why is this bad?
    rcl applies a section only to the nodes whose fully qualified name it
    matches. A section for `talker` when the node runs as `/robot1/talker`
    (a namespace added by the launch file), or a misspelt node name, is
    silently ignored: every value in it is lost and the node runs with its
    defaults, with no error or warning at run time.

    ## Known problems
    The file is judged over every launch system that passes it; when any node
    receiving it has a name or namespace the analysis cannot determine (an
    executable whose code is not in the workspace and whose name the launch
    file does not set, a launch argument without a value), the file is not
    judged. The finding is located in the YAML file, so `check`, SARIF and
    the pre-commit hook show it; flake8 itself only reads Python files.

    ## Example
    ```python
    Node(package='demo', executable='talker', namespace='robot1',
         parameters=['config/talker.yaml'])
    ```
    ```yaml
    talker:
      ros__parameters:
        rate: 5.0
    ```

    ## Use instead
    ```yaml
    /robot1/talker:   # or /**/talker, or /** for every node started with the file
      ros__parameters:
        rate: 5.0
    ```

    ## Options
    None.
    """

    code = "ROS205"
    name = "unmatched-parameter-section"
    level = "warning"
    precision = "high"  # SARIF/code-scanning precision: how often a finding is a real problem
    summary = ("a parameter YAML section (node key) that no node started with that file matches: "
               "all its values are ignored")

    def check(self, graph: RosGraph, config: RuleConfig) -> Iterator[Finding]:
        uses: dict[str, _FileUse] = {}
        for system in graph.systems:
            for launched in system.nodes:
                fqns = _launched_fqns(system, launched)
                for ref in launched.param_files:
                    if ref.path is None:
                        continue
                    use = uses.setdefault(ref.path, _FileUse())
                    use.sections = system.param_sections.get(ref.path, use.sections)
                    use.passed_at.add(ref.location)
                    if fqns is None:
                        use.open = True
                    else:
                        use.fqns |= fqns
        for path in sorted(uses):
            use = uses[path]
            if use.open or not use.fqns:
                continue
            for section in use.sections:
                if not any(section.matches(fqn) for fqn in use.fqns):
                    yield self._finding(section, use)

    def _finding(self, section, use: _FileUse) -> Finding:
        started = sorted(use.fqns)
        message = (f"parameter section '{section.pattern}' matches no node started with "
                   f"{section.location.path} ({', '.join(started[:3])}{', ...' if len(started) > 3 else ''}); "
                   f"its {len(section.settings)} value(s) are ignored")
        close = [fqn for fqn in started if names.edit_distance(fqn, section.pattern, 3) <= 3
                 or fqn.rsplit("/", 1)[-1] == section.pattern.rsplit("/", 1)[-1]]
        if close:
            message += f"; did you mean '{close[0]}'?"
        related = tuple((location, "the launch file passes the parameter file here")
                        for location in sorted(use.passed_at)[:3])
        return Finding(section.location, self.code, message, related)
