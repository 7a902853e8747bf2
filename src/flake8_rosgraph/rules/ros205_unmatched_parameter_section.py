"""ROS205 unmatched-parameter-section."""
from __future__ import annotations

import posixpath
from dataclasses import dataclass, field
from typing import Iterator

from ..graph import names
from ..graph.model import Location, RosGraph
from ..launch.model import LaunchedNode, System
from ..launch.param_files import Section
from .base import Finding, Rule, RuleConfig

#: Unresolved parts of a launched node that may change the name rcl gives its nodes.
_NAME_CHANGERS = ("name", "namespace", "ros_arguments")


@dataclass
class _FileUse:
    """Every node started with one parameter file, over all launch systems."""

    sections: list[Section] = field(default_factory=list)
    fqns: set[str] = field(default_factory=set)
    references: set[Location] = field(default_factory=set)
    #: Some node started with the file has a name or namespace the analysis does not know.
    unknown: bool = False


def _fqns(system: System, launched: LaunchedNode) -> list[str] | None:
    """The fully qualified names of the nodes ``launched`` starts, or ``None`` if one is unknown."""
    if any(launched.is_unresolved(what) for what in _NAME_CHANGERS):
        return None
    if launched.target.status == "found":
        found = [i.node.fqn for i in system.instances if i.launched is launched]
        return None if not found or None in found else [f for f in found if f is not None]
    if launched.name is not None and launched.namespace is not None:
        # `__node:=` and `__ns:=` rename every node of an executable the analysis cannot read.
        return [names.fqn(launched.name, names.normalize_namespace(launched.namespace))]
    return None


def _uses(systems: list[System]) -> dict[str, _FileUse]:
    uses: dict[str, _FileUse] = {}
    unresolved: list[str] = []
    for system in systems:
        for launched in system.nodes:
            for ref in launched.param_files:
                if ref.path is None:
                    unresolved.append(ref.written)
                    continue
                # An OpaqueFunction not followed, or an include not followed that is handed the
                # file (or values the analysis cannot read), may pass it to nodes it does not see.
                fqns = None if system.may_hand_unseen(ref.path) else _fqns(system, launched)
                use = uses.setdefault(ref.path, _FileUse())
                use.sections = system.parameter_files.get(ref.path, use.sections)
                use.references.add(ref.location)
                if fqns is None:
                    use.unknown = True
                else:
                    use.fqns.update(fqns)
    for path, use in uses.items():
        # a reference the analysis could not resolve elsewhere may well be this file, if it names it
        if any(posixpath.basename(path) in written for written in unresolved):
            use.unknown = True
    return uses


class UnmatchedParameterSection(Rule):
    """## What it does
    Checks that every section of a parameter YAML file (a node key above
    `ros__parameters`: `talker`, `/robot/talker`, nested `robot: talker:`,
    or with the wildcards `*` and `/**` as rcl matches them) matches at
    least one node that the workspace's launch files start with that file.

    ## Why is this bad?
    rcl hands a node only the sections whose key matches its fully
    qualified name. A section for a node name that was changed, or
    misspelt, or written without the namespace the launch file pushes,
    matches nothing: every value in it is silently ignored and the node
    runs with its defaults.

    ## Known problems
    A file is judged over every launch file that passes it, so a shared
    file (one section per node of a stack) is fine as long as some launch
    file starts each node. It stays quiet when a node started with the file
    has a name or namespace the analysis cannot determine (from a launch
    argument without a default, or a C++ executable whose name the launch
    file does not set), and for files passed by a launch file that may hand
    them to nodes it does not see (an `OpaqueFunction` it cannot follow, an
    include it cannot follow that is handed the file or values it cannot
    read, a parameter file it cannot resolve such as `RewrittenYaml`). An
    include of an installed package's launch file (a camera driver's) that
    is handed other values does not make the file unknown. Only parameter
    files that some launch file passes are judged. The finding is located
    in the YAML file, so flake8 (which sees only `.py` files) does not show
    it; use `flake8-rosgraph check` or SARIF.

    ## Example
    ```yaml
    # config/camera.yaml, passed to Node(..., name='front_camera', namespace='robot')
    camera:
      ros__parameters:
        exposure: 0.02
    ```

    ## Use instead
    ```yaml
    /robot/front_camera:
      ros__parameters:
        exposure: 0.02
    ```

    ## Options
    None.
    """

    code = "ROS205"
    name = "unmatched-parameter-section"
    level = "warning"
    precision = "high"  # SARIF/code-scanning precision: how often a finding is a real problem
    summary = "a parameter YAML section matches no node started with that file: its values are ignored"

    def check(self, graph: RosGraph, config: RuleConfig) -> Iterator[Finding]:
        for _path, use in sorted(_uses(graph.systems).items()):
            if use.unknown or not use.fqns:
                continue
            for section in use.sections:
                if section.location is None or not section.settings \
                        or any(section.matches(fqn) for fqn in use.fqns):
                    continue
                yield self._finding(section, use)

    def _finding(self, section: Section, use: _FileUse) -> Finding:
        started = sorted(use.fqns)
        shown = ", ".join(started[:4]) + (", …" if len(started) > 4 else "")
        count = len(section.settings)
        message = (f"parameter section '{section.pattern}' matches no node started with this file "
                   f"({shown}): its {count} value{'s' if count != 1 else ''} "
                   f"{'are' if count != 1 else 'is'} ignored")
        # a misspelt node key, or the right node name outside the namespace the node runs in
        close = sorted(f for f in started if names.edit_distance(f, section.pattern, 3) <= 3) or \
            sorted(f for f in started if f.rsplit("/", 1)[-1] == section.pattern.rsplit("/", 1)[-1])
        if close:
            message += f"; did you mean '{close[0]}'?"
        related = tuple((ref, "parameter file passed here") for ref in sorted(use.references))
        return Finding(section.location, self.code, message, related)
