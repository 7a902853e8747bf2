"""docs/github-code-scanning.md: the workflows a user copies must be valid and call the CLI correctly."""
from __future__ import annotations

import re
import shlex

import pytest

from flake8_rosgraph.cli import make_parser

from .conftest import REPO

yaml = pytest.importorskip("yaml", reason="PyYAML comes with pre-commit, a test dependency")

DOC = REPO / "docs" / "github-code-scanning.md"


def workflows() -> list[dict]:
    blocks = re.findall(r"```yaml\n(.*?)```", DOC.read_text(encoding="utf-8"), flags=re.S)
    return [yaml.safe_load(block) for block in blocks]


def commands(workflow: dict) -> list[str]:
    return [step["run"] for job in workflow["jobs"].values() for step in job["steps"] if "run" in step]


def test_the_documented_workflows_are_valid_and_call_the_cli_correctly():
    found = workflows()
    assert len(found) == 2
    for workflow in found:
        assert workflow["name"] and workflow["jobs"]
        assert workflow.get(True, workflow.get("on"))  # YAML 1.1 reads the key `on` as true
        for job in workflow["jobs"].values():
            assert job["runs-on"] == "ubuntu-latest"
            assert job["steps"][0]["uses"].startswith("actions/checkout@")
        checks = [c for c in commands(workflow) if c.startswith("flake8-rosgraph")]
        assert len(checks) == 1
        argv = shlex.split(checks[0].split("||")[0])[1:]
        args = make_parser().parse_args(argv)  # raises SystemExit on a flag the CLI does not have
        assert args.command == "check"
    scanning, annotations = found
    assert scanning["permissions"]["security-events"] == "write"
    upload = [s for s in scanning["jobs"]["rosgraph"]["steps"] if "upload-sarif" in s.get("uses", "")]
    assert upload and upload[0]["with"]["sarif_file"] == "rosgraph.sarif"
    assert "--sarif rosgraph.sarif" in commands(scanning)[-1]
    assert "--format github" in commands(annotations)[-1]
