"""Roots that are not workspaces, and mistakes of the user: a message and exit status 2, never a walk or a shrug.

A file outside any workspace must not make the tool walk ``/`` or the home
folder; a root given explicitly (``--root``, ``--rosgraph-root``,
``ROSGRAPH_ROOT``) that is missing or not a folder is an error; a typo in a
rule code, an unwritable SARIF file and the like are user errors with a user
message, and ``--debug`` shows the traceback.
"""
from __future__ import annotations

import os
import sys
from pathlib import Path

import pytest

from flake8_rosgraph.root import MAX_UNMARKED_PYTHON_FILES, RootRefused, discover_root

from .harness import clean_env, flake8_executable, run
from .metadata_workspace import CHAT, TALKER, TIGHT_MEMORY, write_workspace

posix_only = pytest.mark.skipif(os.name != "posix", reason="POSIX home and root folders")


@pytest.fixture
def ws(tmp_path: Path) -> Path:
    return write_workspace(tmp_path / "ws")


def tool(*args: str, cwd: Path, env: dict[str, str] | None = None):
    done = run([sys.executable, "-m", "flake8_rosgraph", *args], cwd, env or clean_env(),
               memory_cap=TIGHT_MEMORY, hang_guard=60)
    assert done is not None
    return done


def flake8(*args: str, cwd: Path, env: dict[str, str] | None = None):
    done = run([flake8_executable(), "--isolated", "--select", "ROS", *args], cwd, env or clean_env(),
               memory_cap=TIGHT_MEMORY, hang_guard=60)
    assert done is not None
    return done


# -- roots -------------------------------------------------------------------------------------

@posix_only
def test_lone_file_run_from_the_filesystem_root_stays_in_its_folder(tmp_path: Path) -> None:
    lone = tmp_path / "scratch" / "node.py"
    lone.parent.mkdir()
    lone.write_text(TALKER)
    assert discover_root(lone, given=Path("/")) == lone.parent


@posix_only
def test_lone_file_in_home_is_analysed_alone(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    home = tmp_path / "home"
    (home / "projects" / "other").mkdir(parents=True)
    (home / "projects" / "other" / "broken.py").write_text("def (:\n")
    lone = home / "node.py"
    lone.write_text(TALKER)
    monkeypatch.setenv("HOME", str(home))
    assert discover_root(lone, given=home) == lone
    env = clean_env(HOME=str(home), XDG_CACHE_HOME=str(tmp_path / "user-cache"))
    done = tool("check", str(lone), "--format", "json", cwd=home, env=env)
    assert done.returncode in (0, 1), done.explain()
    assert "broken.py" not in done.stdout + done.stderr, "walked the home folder"
    assert not (home / ".rosgraph-cache").exists()
    flaked = flake8(str(lone), cwd=home, env=env)
    assert flaked.returncode in (0, 1) and "Traceback" not in flaked.stderr, flaked.explain()
    assert not (home / ".rosgraph-cache").exists()


@pytest.mark.parametrize("kind", ["missing", "file", "empty"])
def test_check_root_must_be_a_folder_holding_the_paths(ws: Path, tmp_path: Path, kind: str) -> None:
    root = tmp_path / kind
    if kind == "file":
        root.write_text("")
    elif kind == "empty":
        root.mkdir()
    for args, env in (((f"--root={root}",), None), ((), clean_env(ROSGRAPH_ROOT=str(root)))):
        done = tool("check", str(ws), *args, cwd=ws, env=env)
        assert done.returncode == 2, done.explain()
        assert "internal error" not in done.stderr and "Traceback" not in done.stderr
        expected = {"missing": "no such folder", "file": "not a folder", "empty": "not inside"}[kind]
        assert expected in done.stderr, done.explain()
        if env is not None and kind != "empty":
            assert "ROSGRAPH_ROOT" in done.stderr


@pytest.mark.parametrize("kind", ["missing", "file"])
def test_flake8_root_must_be_a_folder(ws: Path, tmp_path: Path, kind: str) -> None:
    root = tmp_path / kind
    if kind == "file":
        root.write_text("")
    for args, env in (((f"--rosgraph-root={root}",), None), ((), clean_env(ROSGRAPH_ROOT=str(root)))):
        done = flake8(*args, str(ws / CHAT / "chat_pkg" / "talker.py"), cwd=ws, env=env)
        assert done.returncode == 2, done.explain()
        assert "flake8: error:" in done.stderr and ("--rosgraph-root" if env is None else "ROSGRAPH_ROOT") \
            in done.stderr, done.explain()
        assert "Traceback" not in done.stderr


def test_without_a_marker_the_root_is_the_folder_named_not_the_current_one(tmp_path: Path) -> None:
    """``check pkg`` run from a markerless parent analyses ``pkg``, not its neighbours."""
    parent = tmp_path / "downloads"
    package = parent / "chat_pkg"
    (package / "chat_pkg").mkdir(parents=True)
    (package / "package.xml").write_text("<package format='3'><name>chat_pkg</name></package>\n")
    (package / "chat_pkg" / "talker.py").write_text(TALKER)
    (parent / "junk").mkdir()
    (parent / "junk" / "broken.py").write_text("def (:\n")
    for named in (package, Path("chat_pkg")):
        done = tool("check", str(named), "--format", "json", cwd=parent)
        assert done.returncode in (0, 1) and "broken.py" not in done.stdout + done.stderr, done.explain()
        flaked = flake8("--rosgraph-debug", str(named), cwd=parent)
        assert flaked.returncode in (0, 1) and "broken.py" not in flaked.stdout + flaked.stderr, flaked.explain()
    whole = tool("check", ".", "--format", "json", cwd=parent)
    assert "broken.py" in whole.stdout, "the folder named is analysed whole"


def _library_tree(folder: Path, files: int) -> None:
    """A vendored library: many small modules in a few packages, none of them ROS."""
    for index in range(files):
        module = folder / "vendored" / f"part{index % 7}" / f"mod{index}.py"
        module.parent.mkdir(parents=True, exist_ok=True)
        module.write_text(f"VALUE = {index}\n")


@pytest.fixture
def downloads(tmp_path: Path) -> Path:
    """A big folder that no marker makes a workspace, with one rclpy script in it."""
    folder = tmp_path / "downloads"
    _library_tree(folder, MAX_UNMARKED_PYTHON_FILES + 50)
    (folder / "talker.py").write_text(TALKER)
    return folder


def test_big_unmarked_folder_is_refused_with_the_way_out(downloads: Path) -> None:
    with pytest.raises(RootRefused):
        discover_root(downloads / "talker.py", given=downloads)
    done = tool("check", ".", cwd=downloads)
    assert done.returncode == 2, done.explain()
    assert str(downloads) in done.stderr and "--root DIR" in done.stderr and "ROSGRAPH_ROOT" in done.stderr
    assert "Traceback" not in done.stderr and not (downloads / ".rosgraph-cache").exists()
    explicit = tool("check", ".", f"--root={downloads}", "--format", "json", cwd=downloads)
    assert explicit.returncode in (0, 1), explicit.explain()


def test_big_unmarked_folder_costs_flake8_one_line_not_its_other_checks(downloads: Path) -> None:
    (downloads / "unused.py").write_text("import os\n")
    done = flake8("--select", "ROS,F", "talker.py", "unused.py", cwd=downloads)
    assert done.returncode == 1, done.explain()
    refusals = [line for line in done.stdout.splitlines() if "ROS000" in line]
    assert len(refusals) == 1 and "--rosgraph-root DIR" in refusals[0], done.explain()
    assert "F401" in done.stdout, "flake8's own checks must still run"
    assert not (downloads / ".rosgraph-cache").exists()


def test_unmarked_folder_below_the_limit_and_big_packages_are_analysed(tmp_path: Path) -> None:
    scripts = tmp_path / "scripts"
    _library_tree(scripts, MAX_UNMARKED_PYTHON_FILES - 50)
    (scripts / "talker.py").write_text(TALKER)
    assert discover_root(scripts / "talker.py", given=scripts) == scripts
    package = tmp_path / "generated_pkg"
    _library_tree(package / "generated_pkg", MAX_UNMARKED_PYTHON_FILES + 50)
    (package / "package.xml").write_text("<package format='3'><name>generated_pkg</name></package>\n")
    (package / "generated_pkg" / "talker.py").write_text(TALKER)
    assert discover_root(package / "generated_pkg" / "talker.py", given=package) == package


# -- user errors -------------------------------------------------------------------------------

@pytest.mark.parametrize("option", ["--select=ROS999", "--extend-select=ROS2X", "--ignore=RSO001"])
def test_unknown_rule_codes_are_rejected(ws: Path, option: str) -> None:
    done = tool("check", str(ws), option, cwd=ws)
    assert done.returncode == 2 and "unknown rule code" in done.stderr, done.explain()
    assert "internal error" not in done.stderr


def test_known_code_prefixes_are_accepted(ws: Path) -> None:
    done = tool("check", str(ws), "--select=ROS2", "--ignore=ROS00", cwd=ws)
    assert done.returncode == 1 and "ROS201" in done.stdout, done.explain()


def test_failed_sarif_write_is_an_error(ws: Path, tmp_path: Path) -> None:
    target = tmp_path / "a-folder"
    target.mkdir()
    done = tool("check", str(ws), f"--sarif={target}", cwd=ws)
    assert done.returncode == 2, done.explain()
    assert "cannot write the SARIF file" in done.stderr and "internal error" not in done.stderr
    flaked = flake8(f"--rosgraph-sarif={target}", str(ws), cwd=ws)
    assert flaked.returncode != 0 and "could not write the SARIF file" in flaked.stderr, flaked.explain()


def test_clean_flake8_run_with_failed_sarif_write_is_an_error(ws: Path, tmp_path: Path) -> None:
    target = tmp_path / "a-folder"
    target.mkdir()
    clean = ws / "src" / "drive_pkg" / "tool.py"
    clean.write_text("x = 1\n")
    flaked = flake8(f"--rosgraph-sarif={target}", str(clean), cwd=ws)
    assert flaked.returncode != 0, flaked.explain()


def test_debug_shows_the_traceback(ws: Path, tmp_path: Path) -> None:
    missing = tmp_path / "nowhere"
    quiet = tool("check", str(ws), f"--root={missing}", cwd=ws)
    assert "Traceback" not in quiet.stderr and "no such folder" in quiet.stderr
    loud = tool("check", str(ws), f"--root={missing}", "--debug", cwd=ws)
    assert loud.returncode == 2 and "Traceback (most recent call last)" in loud.stderr, loud.explain()
    assert "no such folder" in loud.stderr


def test_other_plugins_codes_in_the_shared_configuration_are_not_ours(ws: Path) -> None:
    """A repository's .flake8 selects and ignores pycodestyle/bugbear codes for flake8; ``check``
    keeps its ROS rules as they are, and still refuses a ROS code there that names no rule."""
    (ws / ".flake8").write_text("[flake8]\nselect = E,F,W,C,B590\nextend-ignore = W503, E203, E501\n")
    done = tool("check", str(ws), cwd=ws)
    assert done.returncode == 1 and "ROS201" in done.stdout, done.explain()
    (ws / ".flake8").write_text("[flake8]\nextend-select = ROS010\nignore = E203, ROS2\n")
    done = tool("check", str(ws), cwd=ws)
    assert done.returncode in (0, 1) and "ROS201" not in done.stdout, done.explain()
    (ws / ".flake8").write_text("[flake8]\nextend-ignore = E203, ROS99\n")
    done = tool("check", str(ws), cwd=ws)
    assert done.returncode == 2 and "unknown rule code(s): ROS99" in done.stderr, done.explain()
