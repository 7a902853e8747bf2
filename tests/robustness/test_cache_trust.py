"""The workspace cache as an attack surface: committed entries, foreign folders, links, odd file names.

The cache must only ever delete its own files in its own folder, never write
through a link, never trust an entry this user did not write on this machine,
and key every file the analysis reads.
"""
from __future__ import annotations

import json
import os
import stat
import sys
from pathlib import Path

import pytest

from flake8_rosgraph import cache
from flake8_rosgraph.options import Settings

from .harness import clean_env, run
from .metadata_workspace import CHAT, TIGHT_MEMORY, write_workspace

posix_only = pytest.mark.skipif(os.name != "posix", reason="needs POSIX symlinks and modes")
SETTINGS = Settings()


@pytest.fixture(autouse=True)
def private_secret(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """Each test gets its own user cache folder (and so its own signing secret)."""
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "user-cache"))
    cache.machine_secret.cache_clear()
    yield tmp_path / "user-cache"
    cache.machine_secret.cache_clear()


@pytest.fixture
def ws(tmp_path: Path) -> Path:
    return write_workspace(tmp_path / "ws")


def codes(report: cache.WorkspaceReport) -> set[tuple[str, str, int]]:
    return {(f.code, f.location.path, f.location.line) for f in report.findings}


def entry_of(root: Path, settings: Settings = SETTINGS) -> Path:
    folder = settings.cache_dir or root / cache.CACHE_DIR_NAME
    return folder / f"{cache.cache_key(root, settings)}.json"


def forged_entry(root: Path) -> dict:
    return {"format": cache.ENTRY_FORMAT, "key": cache.cache_key(root, SETTINGS), "diagnostics": [],
            "findings": [{"path": "src/chat_pkg/chat_pkg/talker.py", "line": 1, "column": 1, "code": "ROS001",
                          "message": "forged\n\x1b[2Ksrc/x.py:1:1: F401 fake", "related": []}]}


@posix_only
def test_secret_is_private_and_reused(private_secret: Path, ws: Path) -> None:
    cache.load_or_build(ws, SETTINGS)
    key_file = private_secret / "flake8-rosgraph" / "key"
    assert stat.S_IMODE(key_file.stat().st_mode) == 0o600
    first = key_file.read_bytes()
    cache.machine_secret.cache_clear()
    cache.load_or_build(ws, SETTINGS)
    assert key_file.read_bytes() == first


@pytest.mark.parametrize("signature", [None, "0" * 64, "signed-elsewhere"])
def test_committed_entry_is_not_trusted(ws: Path, signature: str | None) -> None:
    """An entry in the repository (its key is computable from the release and the sources) is ignored."""
    expected = cache.build_report(ws, SETTINGS)
    entry = entry_of(ws)
    entry.parent.mkdir()
    obj = forged_entry(ws)
    if signature == "signed-elsewhere":  # a valid signature, with another machine's secret
        entry.write_text(cache.signed_text(obj, b"another machine's secret, 32 bytes+"))
    elif signature is not None:
        entry.write_text(f"{signature}\n{json.dumps(obj)}")
    else:
        entry.write_text(json.dumps(obj))
    assert cache.load_or_build(ws, SETTINGS) == expected


def test_own_entry_is_reused(ws: Path) -> None:
    first = cache.load_or_build(ws, SETTINGS)
    entry = entry_of(ws)
    signature, body = entry.read_text().split("\n", 1)
    stored = json.loads(body)
    stored["findings"] = []  # tampering after signing breaks the signature
    entry.write_text(f"{signature}\n{json.dumps(stored, sort_keys=True, separators=(',', ':'))}")
    cache.start_run()
    assert cache.load_or_build(ws, SETTINGS) == first
    assert json.loads(entry.read_text().split("\n", 1)[1])["findings"], "the tampered entry was not replaced"


@posix_only
def test_committed_entry_linked_to_dev_zero(ws: Path, tmp_path: Path) -> None:
    if not Path("/dev/zero").exists():
        pytest.skip("no /dev/zero")
    env = clean_env(XDG_CACHE_HOME=str(tmp_path / "user-cache"))
    entry = entry_of(ws)
    entry.parent.mkdir()
    entry.symlink_to("/dev/zero")
    done = run([sys.executable, "-m", "flake8_rosgraph", "check", str(ws)], ws, env, memory_cap=TIGHT_MEMORY,
               hang_guard=60)
    assert done is not None and done.returncode == 1, done and done.explain()
    assert "ROS201" in done.stdout


@posix_only
@pytest.mark.parametrize("marker", [".gitignore", "COLCON_IGNORE", "CACHEDIR.TAG"])
def test_dangling_marker_link_is_not_followed(ws: Path, tmp_path: Path, marker: str) -> None:
    target = tmp_path / "victim" / "created-by-the-tool"
    target.parent.mkdir()
    folder = ws / cache.CACHE_DIR_NAME
    folder.mkdir()
    (folder / marker).symlink_to(target)
    expected = cache.build_report(ws, SETTINGS)
    assert cache.load_or_build(ws, SETTINGS) == expected
    assert not target.exists()
    assert list(folder.iterdir()) == [folder / marker], "wrote into a folder it does not own"


@posix_only
def test_cache_folder_that_is_a_link_is_not_used(ws: Path, tmp_path: Path) -> None:
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    (ws / cache.CACHE_DIR_NAME).symlink_to(elsewhere, target_is_directory=True)
    cache.load_or_build(ws, SETTINGS)
    assert list(elsewhere.iterdir()) == []


def test_foreign_folder_is_never_written_or_pruned(ws: Path, tmp_path: Path) -> None:
    """``--cache-dir`` pointed at a folder of the user's: their files stay, no markers appear."""
    mine = tmp_path / "reports"
    mine.mkdir()
    for i in range(20):
        (mine / f"{i:064x}.json").write_text("{}")  # even names like the cache's own entries
        (mine / f"report{i}.json").write_text("{}")
    before = sorted(p.name for p in mine.iterdir())
    settings = Settings(cache_dir=mine)
    for i in range(3):
        (ws / CHAT / "chat_pkg" / f"extra{i}.py").write_text("x = 1\n")
        cache.start_run()
        cache.load_or_build(ws, settings)
    assert sorted(p.name for p in mine.iterdir()) == before


def test_cache_dir_at_the_workspace_root_does_not_hide_it_from_colcon(ws: Path) -> None:
    cache.load_or_build(ws, Settings(cache_dir=ws))
    assert not (ws / "COLCON_IGNORE").exists() and not (ws / ".gitignore").exists()


def test_empty_folder_is_adopted_and_pruning_keeps_foreign_files(ws: Path, tmp_path: Path) -> None:
    folder = tmp_path / "empty-cache"
    folder.mkdir()
    settings = Settings(cache_dir=folder)
    cache.load_or_build(ws, settings)
    assert (folder / cache.OWNER_MARKER).is_file()
    (folder / "notes.json").write_text("{}")  # dropped in later by someone else
    for i in range(cache.KEEP_ENTRIES + 4):
        (ws / CHAT / "chat_pkg" / "version.py").write_text(f"VERSION = {i}\n")
        cache.start_run()
        cache.load_or_build(ws, settings)
    # The input-digest index (written once files have settled) and the outlines are not entries.
    entries = [p for p in folder.glob("*.json") if p.name not in ("notes.json", cache.INPUT_INDEX, cache.OUTLINES)]
    assert len(entries) == cache.KEEP_ENTRIES
    assert (folder / "notes.json").is_file()


@pytest.mark.parametrize("rel", ["src/drive_pkg/CMakeLists.txt", "src/ignored/COLCON_IGNORE",
                                 "src/ignored/node.py", "src/chat_pkg/config/listener.yaml",
                                 "src/chat_pkg/package.xml"])
def test_every_read_file_is_in_the_key(ws: Path, rel: str) -> None:
    (ws / "src" / "ignored").mkdir()
    (ws / "src" / "ignored" / "COLCON_IGNORE").write_text("")
    (ws / "src" / "ignored" / "node.py").write_text("import rclpy\n")
    before = cache.cache_key(ws, SETTINGS)
    with (ws / rel).open("a") as handle:
        handle.write("\n# changed\n")
    assert cache.cache_key(ws, SETTINGS) != before


def test_cmake_change_is_seen_through_the_cache(ws: Path) -> None:
    """Fixing a missing executable in CMakeLists.txt clears the ROS201 on the next cached run."""
    (ws / CHAT / "launch" / "drive.launch.xml").write_text(
        '<launch>\n  <node pkg="drive_pkg" exec="odom"/>\n</launch>\n')
    assert ("ROS201", f"{CHAT}/launch/drive.launch.xml", 2) in codes(cache.load_or_build(ws, SETTINGS))
    cmake = ws / "src" / "drive_pkg" / "CMakeLists.txt"
    cmake.write_text(cmake.read_text() + "add_executable(odom src/odom.cpp)\n")
    cache.start_run()
    assert ("ROS201", f"{CHAT}/launch/drive.launch.xml", 2) not in codes(cache.load_or_build(ws, SETTINGS))


@posix_only
def test_non_utf8_file_name_in_the_key(ws: Path) -> None:
    (ws / os.fsdecode(b"src/chat_pkg/chat_pkg/na\xefve.py")).write_text("x = 1\n")
    first = cache.cache_key(ws, SETTINGS)
    assert first == cache.cache_key(ws, SETTINGS)
    report = cache.load_or_build(ws, SETTINGS)
    assert ("ROS201", f"{CHAT}/launch/bringup.launch.xml", 2) in codes(report)
