"""Workspace root discovery: colcon workspace, then version-control root, then a local fallback."""
from __future__ import annotations

from pathlib import Path

from flake8_rosgraph.root import discover_root, find_colcon_root, find_vcs_root

from .conftest import write_tree


def test_unbuilt_colcon_workspace_is_found_from_a_package_file(tmp_path: Path) -> None:
    ws = write_tree(tmp_path / "ws", {"src/repo/pkg/package.xml": "", "src/repo/pkg/pkg/node.py": ""})
    (ws / "src" / "repo" / ".git").mkdir()
    assert discover_root(ws / "src/repo/pkg/pkg/node.py") == ws


def test_built_colcon_workspace_is_found_by_its_markers(tmp_path: Path) -> None:
    ws = write_tree(tmp_path / "ws", {"src/tools/script.py": "", "build/COLCON_IGNORE": ""})
    assert find_colcon_root(ws / "src/tools/script.py") == ws


def test_a_workspace_directory_given_directly_is_its_own_root(tmp_path: Path) -> None:
    ws = write_tree(tmp_path / "ws", {"src/pkg/package.xml": "", "src/pkg/pkg/node.py": ""})
    assert discover_root(ws) == ws
    assert discover_root(ws / "src") == ws


def test_src_layout_python_project_is_not_a_colcon_workspace(tmp_path: Path) -> None:
    repo = write_tree(tmp_path / "repo", {"src/lib/module.py": "", "pkg/package.xml": "", "pkg/src/x.py": ""})
    (repo / ".git").mkdir()
    assert find_colcon_root(repo / "src/lib/module.py") is None
    assert find_colcon_root(repo / "pkg/src/x.py") is None
    assert discover_root(repo / "pkg/src/x.py") == repo


def test_vcs_root_accepts_git_worktree_files_and_other_systems(tmp_path: Path) -> None:
    worktree = write_tree(tmp_path / "wt", {".git": "gitdir: elsewhere\n", "a/b.py": ""})
    hg = write_tree(tmp_path / "hgrepo", {"a/b.py": ""})
    (hg / ".hg").mkdir()
    assert find_vcs_root(worktree / "a/b.py") == worktree
    assert find_vcs_root(hg / "a/b.py") == hg


def test_nearest_workspace_wins_over_an_enclosing_repository(tmp_path: Path) -> None:
    repo = write_tree(tmp_path / "repo", {"examples/src/demo/package.xml": "", "examples/src/demo/demo/n.py": ""})
    (repo / ".git").mkdir()
    assert discover_root(repo / "examples/src/demo/demo/n.py") == repo / "examples"


def test_fallback_is_the_package_or_the_current_directory(tmp_path: Path) -> None:
    loose = write_tree(tmp_path / "loose", {"pkg/package.xml": "", "pkg/pkg/node.py": "", "other/x.py": ""})
    assert discover_root(loose / "pkg/pkg/node.py", given=tmp_path / "elsewhere") == loose / "pkg"
    assert discover_root(loose / "pkg/pkg/node.py", given=loose) == loose
    assert discover_root(loose / "other/x.py", given=tmp_path / "elsewhere") == loose / "other"
