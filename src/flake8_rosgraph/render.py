"""What ``flake8-rosgraph graph`` draws: the graph, the findings on it, in the format asked for.

The writers (:mod:`.graph.dot`, :mod:`.graph.mermaid`, :mod:`.graph.html`)
know nothing of analysis or rules; this module gathers what they draw — the
rules' findings (judged as launched, as ``check`` judges them), the exempt
names, the package of each folder — and, for the HTML page, one view for the
code-level graph plus one for each launch system.
"""
from __future__ import annotations

import os
from pathlib import Path

from .escaping import escape_text
from .findings import Finding, RuleConfig
from .graph.html import View, to_html
from .graph.model import RosGraph
from .graph.picture import build_picture
from .launch.api import apply, judged_graph
from .launch.model import System
from .launch.packages import find_packages
from .options import Settings
from .rules import RULES, run_rules
from .rules.exempt import ExemptNames


def launched_only(graph: RosGraph, system: System) -> RosGraph:
    """The nodes ``system`` starts (names, namespaces and remaps applied), and nothing else."""
    shown = apply(graph, system)
    shown.nodes = [node for node in shown.nodes if node.launch is not None]
    return shown


class Renderer:
    """Draws one analysed workspace; the findings and exempt names are computed once."""

    def __init__(self, root: Path, graph: RosGraph) -> None:
        self.root = root
        self.graph = graph
        settings = Settings.resolve({}, os.environ)
        config = RuleConfig(external_names=frozenset(settings.external_topics))
        self.exempt = ExemptNames.build(config.external_names)
        self.findings: list[Finding] = run_rules(judged_graph(graph, graph.systems), config,
                                                 select=[rule.code for rule in RULES if rule.default_enabled])
        folder = root if root.is_dir() else root.parent
        self.package_folders = {package.path: name for name, package in find_packages(folder).packages.items()}

    def _view(self, key: str, title: str, graph: RosGraph) -> View:
        return View(key, title, build_picture(graph, self.findings, self.exempt, self.package_folders))

    def dot(self, shown: RosGraph) -> str:
        """DOT text; names keep their line breaks as DOT escapes, and no control character is printed raw."""
        from .graph.dot import picture_to_dot
        text = picture_to_dot(build_picture(shown, self.findings, self.exempt, self.package_folders))
        return "\n".join(escape_text(line) for line in text.split("\n"))

    def mermaid(self, shown: RosGraph) -> str:
        from .graph.mermaid import picture_to_mermaid
        return picture_to_mermaid(build_picture(shown, self.findings, self.exempt, self.package_folders))

    def html(self, launch: System | None) -> str:
        """The page: the system of ``launch`` alone, or the code-level graph and every launch system."""
        title = escape_text(self.root.resolve().name or str(self.root))
        if launch is not None:
            views = [self._view("launch:" + launch.launch_file, launch.launch_file,
                                launched_only(self.graph, launch))]
        else:
            views = [self._view("code", "code-level graph", self.graph)]
            views += [self._view("launch:" + system.launch_file, "launch: " + system.launch_file,
                                 launched_only(self.graph, system))
                      for system in self.graph.systems]
        return to_html(views, title)
