"""Helpers: analyse small in-memory workspaces and read abstract values back."""
from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from flake8_rosgraph.absint.engine import Analysis
from flake8_rosgraph.absint.program import Program
from flake8_rosgraph.analysis import load_stubs
from flake8_rosgraph.workspace import load_workspace


class Analysed:
    def __init__(self, analysis: Analysis):
        self.analysis = analysis

    def value(self, module: str, name: str):
        """The flow-insensitive value of module-global ``name`` after the fixpoint."""
        from flake8_rosgraph.absint.values import BOTTOM
        return self.analysis.heap.get(("g", module, name), BOTTOM)

    def strings(self, module: str, name: str):
        return self.value(module, name).strings()

    def effects(self, kind: str):
        return [e for e in self.analysis.all_effects() if e.kind == kind]


@pytest.fixture
def analyse(tmp_path: Path):
    def run(files: dict[str, str]) -> Analysed:
        for rel, text in files.items():
            path = tmp_path / rel
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(textwrap.dedent(text))
        library, diags = load_stubs()
        assert not diags
        analysis = Analysis(Program(load_workspace(tmp_path).modules), library,
                            every_module_is_entry=True)
        analysis.run()
        return Analysed(analysis)
    return run
