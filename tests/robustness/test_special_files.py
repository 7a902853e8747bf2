"""Workspace entries that are not plain readable files: links, loops, pipes, devices, locked and vanishing files.

None of them may hang or sink the run; the good nodes beside them must all be
extracted; an entry that cannot be read is named by a diagnostic or skipped.
"""
from __future__ import annotations

import os
from pathlib import Path

import pytest

from flake8_rosgraph.analysis import build_graph
from flake8_rosgraph.graph.json_out import to_json_obj

from .harness import (assert_clean_exit, diagnostics_on, entity_keys, flake8_cli, graph_cli, parse_graph,
                      plugin_available)
from .hostile_inputs import GOOD_ENTITIES, GOOD_FILES, GOOD_FLAKE8_FINDINGS, write_files

posix_only = pytest.mark.skipif(os.name != "posix", reason="needs POSIX symlinks, FIFOs and permissions")


@pytest.fixture
def workspace(tmp_path: Path) -> Path:
    root = tmp_path / "ws"
    root.mkdir()
    write_files(root, {k: v.encode() for k, v in GOOD_FILES.items()})
    return root


def graph_of(workspace: Path) -> dict:
    done = graph_cli(workspace, "--format", "json", cwd=workspace.parent)
    assert_clean_exit(done)
    graph = parse_graph(done)
    found = entity_keys(graph)
    assert GOOD_ENTITIES <= found, f"good entities lost: {sorted(GOOD_ENTITIES - found, key=str)}"
    return graph


def _readable_despite_permissions(path: Path) -> bool:
    try:
        with path.open("rb"):
            return True
    except PermissionError:
        return False


@posix_only
def test_symlink_loops(workspace: Path) -> None:
    (workspace / "sub").mkdir()
    (workspace / "sub" / "up").symlink_to("..", target_is_directory=True)
    (workspace / "sub" / "again").symlink_to("../sub", target_is_directory=True)
    (workspace / "self.py").symlink_to("self.py")
    (workspace / "ping.py").symlink_to("pong.py")
    (workspace / "pong.py").symlink_to("ping.py")
    graph = graph_of(workspace)
    for looped in ("self.py", "ping.py", "pong.py"):
        assert diagnostics_on(graph, looped), f"no diagnostic for the looping link {looped}"


@posix_only
def test_dangling_symlink(workspace: Path) -> None:
    (workspace / "gone.py").symlink_to(workspace / "never_existed.py")
    graph = graph_of(workspace)
    assert any("cannot read" in d["message"] for d in diagnostics_on(graph, "gone.py")), graph["diagnostics"]


@posix_only
def test_directory_named_like_a_module(workspace: Path) -> None:
    (workspace / "folder.py").mkdir()
    (workspace / "folder.py" / "inner.py").write_text("import rclpy\nrclpy.create_node('inner_node')\n")
    found = entity_keys(graph_of(workspace))
    assert ("/inner_node", "node", "inner_node", "folder.py/inner.py", 2) in found


@posix_only
def test_fifo_named_like_a_module(workspace: Path) -> None:
    """Opening a FIFO for reading blocks until a writer comes: it must not be read at all."""
    os.mkfifo(workspace / "pipe.py")
    graph_of(workspace)


@posix_only
def test_symlink_to_an_endless_device(workspace: Path) -> None:
    """A device reports size 0 and never ends: the size limit must hold for what is read, not what stat says."""
    if not Path("/dev/zero").exists():
        pytest.skip("no /dev/zero on this system")
    (workspace / "zeros.py").symlink_to("/dev/zero")
    graph_of(workspace)


@posix_only
def test_unreadable_file(workspace: Path) -> None:
    locked = workspace / "locked.py"
    locked.write_text("import rclpy\nrclpy.create_node('locked_node')\n")
    locked.chmod(0)
    try:
        if _readable_despite_permissions(locked):
            pytest.skip("running as root (or with CAP_DAC_OVERRIDE): chmod 000 does not block reading")
        graph = graph_of(workspace)
        assert any("cannot read" in d["message"] for d in diagnostics_on(graph, "locked.py")), \
            graph["diagnostics"]
    finally:
        locked.chmod(0o644)


@posix_only
def test_unreadable_folder(workspace: Path) -> None:
    locked = workspace / "locked_pkg"
    locked.mkdir()
    (locked / "node.py").write_text("import rclpy\nrclpy.create_node('hidden_node')\n")
    locked.chmod(0)
    try:
        if os.access(locked, os.R_OK | os.X_OK):
            pytest.skip("running as root (or with CAP_DAC_OVERRIDE): chmod 000 does not block listing")
        graph_of(workspace)
    finally:
        locked.chmod(0o755)


def test_file_deleted_during_the_run(workspace: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A file listed by the walk but gone when it is read (an editor's atomic save, a branch switch)."""
    import flake8_rosgraph.workspace as ws_module

    vanishing = workspace / "vanishing.py"
    vanishing.write_text("import rclpy\nrclpy.create_node('vanishing_node')\n")
    listed = ws_module.python_files

    def list_then_delete(root: Path, *rest) -> list[Path]:
        files = listed(root, *rest)
        assert vanishing in files
        vanishing.unlink()
        return files

    monkeypatch.setattr(ws_module, "python_files", list_then_delete)
    graph = to_json_obj(build_graph(workspace))
    found = entity_keys(graph)
    assert GOOD_ENTITIES <= found
    assert not any(fqn == "/vanishing_node" for fqn, *_ in found)
    assert any("cannot read" in d["message"] for d in diagnostics_on(graph, "vanishing.py")), \
        graph["diagnostics"]


def test_file_replaced_by_a_folder_during_the_run(workspace: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import flake8_rosgraph.workspace as ws_module

    shifting = workspace / "shifting.py"
    shifting.write_text("import rclpy\n")
    listed = ws_module.python_files

    def list_then_replace(root: Path, *rest) -> list[Path]:
        files = listed(root, *rest)
        shifting.unlink()
        shifting.mkdir()
        return files

    monkeypatch.setattr(ws_module, "python_files", list_then_replace)
    graph = to_json_obj(build_graph(workspace))
    assert GOOD_ENTITIES <= entity_keys(graph)
    assert diagnostics_on(graph, "shifting.py"), graph["diagnostics"]


@posix_only
@pytest.mark.skipif(not plugin_available(), reason="flake8_rosgraph.plugin is not written yet (colleague's task)")
def test_flake8_on_special_files(workspace: Path) -> None:
    """flake8 is told to skip the pipe and the device (it would read them itself); the plugin's own
    walk of the workspace still meets them."""
    (workspace / "sub").mkdir()
    (workspace / "sub" / "up").symlink_to("..", target_is_directory=True)
    (workspace / "gone.py").symlink_to(workspace / "never_existed.py")
    os.mkfifo(workspace / "pipe.py")
    if Path("/dev/zero").exists():
        (workspace / "zeros.py").symlink_to("/dev/zero")
    done = flake8_cli(workspace, "--exclude", "pipe.py,zeros.py")
    assert_clean_exit(done, allowed=(0, 1))
    for where, code in GOOD_FLAKE8_FINDINGS:
        assert any(where in line and f" {code} " in line for line in done.stdout.splitlines()), \
            f"{code} at {where} missing\n{done.explain()}"
