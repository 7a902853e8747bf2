"""The integrations, end to end: the repository's pre-commit hook and ament_flake8 (both slow)."""
from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path
from xml.etree import ElementTree

import pytest

from .conftest import LISTENER, REPO, TALKER, analyses, fake_env, standard_files, write_tree

#: What a source distribution of the hook repository needs.
HOOK_REPO_FILES = ("pyproject.toml", "README.md", "LICENSE", ".pre-commit-hooks.yaml", "src", "stubs")


def _git(*args: str, cwd: Path) -> None:
    subprocess.run(["git", "-c", "user.name=test", "-c", "user.email=test@example.invalid",
                    "-c", "init.defaultBranch=main", *args], cwd=cwd, check=True, capture_output=True)


def _hook_repo(target: Path) -> Path:
    """A committed copy of this repository's installable parts (try-repo needs a git repository)."""
    target.mkdir()
    for name in HOOK_REPO_FILES:
        source = REPO / name
        if source.is_dir():
            shutil.copytree(source, target / name,
                            ignore=shutil.ignore_patterns("__pycache__", "*.egg-info", ".rosgraph-cache"))
        elif source.is_file():
            shutil.copy2(source, target / name)
    if not (target / "README.md").exists():  # pyproject names it as the long description
        (target / "README.md").write_text("flake8-rosgraph\n")
    _git("init", "-q", ".", cwd=target)
    _git("add", "-A", cwd=target)
    _git("commit", "-q", "-m", "hook repository under test", cwd=target)
    return target


@pytest.mark.slow
def test_pre_commit_try_repo_runs_the_hook(tmp_path: Path) -> None:
    hook_repo = _hook_repo(tmp_path / "hook-repo")
    project = write_tree(tmp_path / "project", standard_files())
    _git("init", "-q", ".", cwd=project)
    _git("add", "-A", cwd=project)
    log = tmp_path / "analyses.log"
    env = fake_env(log, PRE_COMMIT_HOME=str(tmp_path / "pre-commit-home"))

    def try_repo(*extra: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run([sys.executable, "-m", "pre_commit", "try-repo", str(hook_repo), "rosgraph",
                               "--verbose", *extra], cwd=project, env=env, capture_output=True, text=True,
                              timeout=900)

    everything = try_repo("--all-files")
    assert everything.returncode == 1, everything.stdout + everything.stderr
    for line in ("src/pkg_a/pkg_a/talker.py:6:10: ROS001 topic '/orphan' has no subscriber",
                 "src/pkg_a/pkg_a/talker.py:7:10: ROS002",
                 "src/pkg_b/pkg_b/listener.py:7:10: ROS003 topic '/nobody' has no publisher"):
        assert line in everything.stdout
    changed = try_repo("--files", "src/pkg_b/pkg_b/listener.py")
    assert "listener.py:7:10: ROS003" in changed.stdout
    assert "talker.py" not in changed.stdout
    assert len(analyses(log)) == 1  # the second run read the workspace cache


LAUNCH_XML = """\
<launch>
  <node pkg="demo_pkg" exec="talker" name="talker"/>
  <node pkg="demo_pkg" exec="listner" name="listener"/>
</launch>
"""


@pytest.mark.slow
def test_pre_commit_hooks_for_launch_files_and_the_whole_workspace(tmp_path: Path) -> None:
    """The real analysis: a changed launch XML triggers the hook and gets its ROS201 there."""
    hook_repo = _hook_repo(tmp_path / "hook-repo")
    project = tmp_path / "project"
    shutil.copytree(REPO / "examples", project)
    launch = project / "src/robot_apps/launch/typo.launch.xml"
    launch.parent.mkdir(parents=True, exist_ok=True)
    launch.write_text(LAUNCH_XML.replace("demo_pkg", "robot_apps").replace('"talker"', '"dashboard"', 1))
    _git("init", "-q", ".", cwd=project)
    _git("add", "-A", cwd=project)
    env = {**fake_env(tmp_path / "unused.log"), "PRE_COMMIT_HOME": str(tmp_path / "pre-commit-home")}
    env.pop("PYTHONPATH")

    def try_repo(hook: str, *extra: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run([sys.executable, "-m", "pre_commit", "try-repo", str(hook_repo), hook,
                               "--verbose", *extra], cwd=project, env=env, capture_output=True, text=True,
                              timeout=900)

    changed = try_repo("rosgraph", "--files", "src/robot_apps/launch/typo.launch.xml")
    assert changed.returncode == 1, changed.stdout + changed.stderr
    assert "src/robot_apps/launch/typo.launch.xml:3:" in changed.stdout and "ROS201" in changed.stdout
    assert "producers.py" not in changed.stdout
    whole = try_repo("rosgraph-workspace", "--files", "README.md")
    assert whole.returncode == 1
    for needle in ("typo.launch.xml:3:", "producers.py:49:9: ROS001", "consumers.py:20:9: ROS003"):
        assert needle in whole.stdout, whole.stdout


def _ros_package(root: Path) -> Path:
    """An ament_python package, style-clean for ament_flake8, with the standard fake findings."""
    return write_tree(root, {
        "package.xml": "<?xml version=\"1.0\"?>\n<package format=\"3\"><name>demo_pkg</name></package>\n",
        "setup.cfg": "[develop]\nscript_dir=$base/lib/demo_pkg\n",
        "resource/demo_pkg": "",
        "demo_pkg/__init__.py": "",
        "demo_pkg/talker.py": TALKER,
        "demo_pkg/listener.py": LISTENER,
    })


@pytest.mark.slow
def test_ament_flake8_reports_ros_findings_in_output_and_xunit(flake8_401_venv: Path, tmp_path: Path) -> None:
    package = _ros_package(tmp_path / "demo_pkg")
    ament_flake8 = flake8_401_venv.parent / "ament_flake8"
    xunit = tmp_path / "results" / "flake8.xunit.xml"
    log = tmp_path / "analyses.log"
    result = subprocess.run([str(ament_flake8), "--xunit-file", str(xunit)], cwd=package,
                            env=fake_env(log), capture_output=True, text=True, timeout=600)
    assert result.returncode == 1, result.stdout + result.stderr
    assert "./demo_pkg/talker.py:6:10: ROS001 topic '/orphan' has no subscriber" in result.stdout
    assert "./demo_pkg/listener.py:7:10: ROS003 topic '/nobody' has no publisher" in result.stdout
    assert "listener.py:6:10" not in result.stdout  # '# noqa: ROS003'
    cases = [case.get("name") for case in ElementTree.parse(xunit).getroot().iter("testcase")]
    assert sorted(cases) == ["ROS001 (./demo_pkg/talker.py:6:10)", "ROS002 (./demo_pkg/talker.py:7:10)",
                             "ROS003 (./demo_pkg/listener.py:7:10)"]

    # ament_flake8 reads only its own config file: the environment configures the plugin
    quiet = subprocess.run([str(ament_flake8)], cwd=package, capture_output=True, text=True, timeout=600,
                           env=fake_env(log, ROSGRAPH_EXTERNAL_TOPICS="/orphan,/nobody"))
    assert "ROS001" not in quiet.stdout and "ROS003" not in quiet.stdout
    assert "ROS002" in quiet.stdout
