"""Shared fixture: the launch test workspace analysed once per session."""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import pytest

from flake8_rosgraph.absint.engine import Analysis
from flake8_rosgraph.absint.program import Program
from flake8_rosgraph.analysis import load_stubs
from flake8_rosgraph.graph.builder import build_graph_from
from flake8_rosgraph.graph.model import RosGraph
from flake8_rosgraph.launch.api import System, systems_for
from flake8_rosgraph.launch.packages import find_packages
from flake8_rosgraph.python_facts import PythonFacts, facts_of
from flake8_rosgraph.workspace import load_workspace

WS = Path(__file__).parent / "ws"


@dataclass
class Analysed:
    root: Path
    python: PythonFacts
    graph: RosGraph
    systems: list[System]

    def system(self, name: str) -> System:
        return next(s for s in self.systems if s.launch_file.endswith("/" + name))


def analyse(root: Path) -> Analysed:
    library, diagnostics = load_stubs()
    assert diagnostics == []
    analysis = Analysis(Program(load_workspace(root).modules), library)
    analysis.run()
    python = facts_of(analysis, [exe for package in find_packages(root).packages.values()
                                 for exe in package.executables.values() if exe.language == "python"])
    graph = build_graph_from(analysis)
    return Analysed(root, python, graph, systems_for(root, graph, python.launches, python.targets))


@pytest.fixture(scope="session")
def ws() -> Analysed:
    return analyse(WS)


@pytest.fixture
def analyse_root():
    """``analyse`` for test modules that build their own workspace under ``tmp_path``."""
    return analyse
