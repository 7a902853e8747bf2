"""The built wheel, installed non-editable into a fresh venv, runs README's main command with its stubs.

An editable install reads the stubs from the source tree, so it cannot show
that the wheel ships them; this test builds the wheel from a copy of the
project (the working tree is left untouched), installs it into a new virtual
environment and runs ``flake8-rosgraph graph examples/ --format json`` there.
The nodes must appear, no diagnostic may be about stubs, and the output must
be byte-identical to the development install's.
"""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
#: Building and installing download from the package index: allow for a slow network.
PIP_TIMEOUT_S = 1200
#: Not part of a source distribution: caches, build output, virtual environments, VCS data.
NOT_SOURCES = shutil.ignore_patterns(".git", "build", "dist", ".venv*", "venv", "__pycache__", "*.egg-info",
                                     ".hypothesis", ".pytest_cache", ".rosgraph-cache", ".tox", ".nox")

pytestmark = pytest.mark.slow


def _run(argv: list[str], cwd: Path, timeout: float = PIP_TIMEOUT_S) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items()
           if not k.startswith(("ROSGRAPH_", "PYTHONPATH", "VIRTUAL_ENV", "PYTHONHOME"))}
    done = subprocess.run(argv, cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout)
    assert done.returncode == 0, f"{' '.join(argv)} failed ({done.returncode}):\n{done.stdout[-3000:]}\n{done.stderr[-3000:]}"
    return done


def _bin(venv: Path, name: str) -> Path:
    return venv / ("Scripts" if os.name == "nt" else "bin") / (name + (".exe" if os.name == "nt" else ""))


@pytest.fixture(scope="module")
def installed(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    base = tmp_path_factory.mktemp("wheel")
    source = base / "source"
    shutil.copytree(REPO, source, ignore=NOT_SOURCES, symlinks=True)
    dist = base / "dist"
    _run([sys.executable, "-m", "pip", "wheel", "--no-deps", "--disable-pip-version-check", "-q", "-w", str(dist),
          str(source)], base)
    wheels = sorted(dist.glob("flake8_rosgraph-*.whl"))
    assert len(wheels) == 1, f"expected one wheel, found {wheels}"
    venv = base / "venv"
    _run([sys.executable, "-m", "venv", str(venv)], base)
    _run([str(_bin(venv, "python")), "-m", "pip", "install", "--disable-pip-version-check", "-q", str(wheels[0])],
         base)
    return {"wheel": wheels[0], "venv": venv}


def test_wheel_ships_the_stubs(installed: dict[str, Path]) -> None:
    with zipfile.ZipFile(installed["wheel"]) as wheel:
        names = set(wheel.namelist())
    shipped = {Path(n).name for n in names if n.startswith("flake8_rosgraph/stubs/") and n.endswith(".toml")}
    in_tree = {p.name for p in (REPO / "stubs").glob("*.toml")}
    assert in_tree and shipped == in_tree, f"stubs in tree {sorted(in_tree)}, in wheel {sorted(shipped)}"
    assert any(n.endswith("entry_points.txt") for n in names)


def test_installed_package_is_not_the_source_tree(installed: dict[str, Path]) -> None:
    done = _run([str(_bin(installed["venv"], "python")), "-c",
                 "import flake8_rosgraph; print(flake8_rosgraph.__file__)"], installed["venv"])
    location = Path(done.stdout.strip()).resolve()
    assert installed["venv"].resolve() in location.parents, f"imported from {location}, not the venv"


def test_readme_main_command(installed: dict[str, Path]) -> None:
    readme = (REPO / "README.md").read_text(encoding="utf-8")
    assert "flake8-rosgraph graph examples/ --format json" in readme, "README's main command changed"
    done = _run([str(_bin(installed["venv"], "flake8-rosgraph")), "graph", "examples/", "--format", "json"], REPO,
                timeout=300)
    graph = json.loads(done.stdout)
    assert graph["schema"] == "rosgraph/1"
    assert len(graph["nodes"]) >= 5, "the example workspace's nodes are missing"
    typed = [e for n in graph["nodes"] for e in n["publishers"] + n["subscriptions"] if e["type"]]
    assert typed, "no publisher or subscription has a message type: the rclpy stubs were not applied"
    stub_problems = [d for d in graph["diagnostics"] if "stub" in d["message"].lower()]
    assert not stub_problems, stub_problems
    assert "stub" not in done.stderr.lower(), done.stderr

    development = _run([sys.executable, "-m", "flake8_rosgraph", "graph", "examples/", "--format", "json"], REPO,
                       timeout=300)
    assert done.stdout == development.stdout, "the installed wheel and the source tree give different graphs"
