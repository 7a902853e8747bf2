"""The distribution as an index would receive it: sdist and wheel built by ``python -m build``, checked by twine."""
from __future__ import annotations

import os
import shutil
import subprocess
import sys
import tarfile
import zipfile
from pathlib import Path

import pytest

from flake8_rosgraph import __version__

REPO = Path(__file__).resolve().parents[1]
NOT_SOURCES = shutil.ignore_patterns(".git", "build", "dist", ".venv*", "venv", "__pycache__", "*.egg-info",
                                     ".hypothesis", ".pytest_cache", ".rosgraph-cache", ".tox", ".nox")

pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def dist(tmp_path_factory: pytest.TempPathFactory) -> Path:
    base = tmp_path_factory.mktemp("dist")
    source = base / "source"
    shutil.copytree(REPO, source, ignore=NOT_SOURCES, symlinks=True)
    env = {k: v for k, v in os.environ.items() if not k.startswith(("ROSGRAPH_", "PYTHONPATH"))}
    out = base / "out"
    built = subprocess.run([sys.executable, "-m", "build", "--outdir", str(out), str(source)], env=env,
                           capture_output=True, text=True, timeout=1200)
    assert built.returncode == 0, built.stdout[-3000:] + built.stderr[-3000:]
    return out


def test_twine_accepts_both_artifacts(dist: Path) -> None:
    files = sorted(str(p) for p in dist.iterdir())
    assert [Path(f).name for f in files] == [f"flake8_rosgraph-{__version__}-py3-none-any.whl",
                                             f"flake8_rosgraph-{__version__}.tar.gz"]
    checked = subprocess.run([sys.executable, "-m", "twine", "check", "--strict", *files],
                             capture_output=True, text=True, timeout=300)
    assert checked.returncode == 0, checked.stdout + checked.stderr


def test_licence_changelog_and_assets_are_shipped(dist: Path) -> None:
    with zipfile.ZipFile(next(dist.glob("*.whl"))) as wheel:
        names = wheel.namelist()
        metadata = wheel.read(next(n for n in names if n.endswith(".dist-info/METADATA"))).decode()
    assert any(n.endswith(".dist-info/licenses/LICENSE") for n in names)
    assert {"flake8_rosgraph/graph/assets/view.js", "flake8_rosgraph/graph/assets/view.css"} <= set(names)
    assert "License-Expression: Apache-2.0" in metadata
    assert f"Version: {__version__}" in metadata
    assert "Classifier: Framework :: Flake8" in metadata and "Project-URL: Changelog" in metadata
    with tarfile.open(next(dist.glob("*.tar.gz"))) as sdist:
        members = {Path(m).name for m in sdist.getnames()}
    assert {"LICENSE", "README.md", "pyproject.toml"} <= members


def test_changelog_has_this_version() -> None:
    text = (REPO / "CHANGELOG.md").read_text(encoding="utf-8")
    assert f"## [{__version__}]" in text
