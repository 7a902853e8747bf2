"""The plugin's on-disk cache under damage and contention, with the real analysis behind it.

Whatever sits in the cache directory — garbage, hostile JSON, folders where
files should be, a file being rewritten while it is read — a lookup must give
exactly the report a fresh analysis gives, and never raise.
"""
from __future__ import annotations

import json
import multiprocessing
import os
import threading
from pathlib import Path
from typing import Callable

import pytest

from .harness import assert_clean_exit, flake8_cli, plugin_available
from .hostile_inputs import GOOD_FILES, GOOD_FLAKE8_FINDINGS, write_files

cache = pytest.importorskip("flake8_rosgraph.cache", reason="the workspace cache (colleague's task) is not written yet")
options = pytest.importorskip("flake8_rosgraph.options")

SETTINGS = options.Settings()


@pytest.fixture
def workspace(tmp_path: Path) -> Path:
    root = tmp_path / "ws"
    write_files(root, {k: v.encode() for k, v in GOOD_FILES.items()})
    return root


def entry_path(root: Path) -> Path:
    return root / cache.CACHE_DIR_NAME / f"{cache.cache_key(root, SETTINGS)}.json"


def _key_of(root: Path) -> str:
    return cache.cache_key(root, SETTINGS)


#: name → function of the workspace root giving the bytes to put where the entry belongs.
DAMAGE: dict[str, Callable[[Path], bytes]] = {
    "empty": lambda root: b"",
    "garbage": lambda root: bytes(range(256)) * 16,
    "invalid_utf8": lambda root: b'{"format": \xff\xfe}',
    "truncated": lambda root: json.dumps({"format": cache.ENTRY_FORMAT, "key": _key_of(root),
                                          "findings": [], "diagnostics": []}).encode()[:-7],
    "json_array": lambda root: b"[1, 2, 3]",
    "json_string": lambda root: b'"entry"',
    "wrong_format_version": lambda root: json.dumps({"format": -1, "key": _key_of(root), "findings": [],
                                                     "diagnostics": []}).encode(),
    "fields_of_wrong_type": lambda root: json.dumps({
        "format": cache.ENTRY_FORMAT, "key": _key_of(root), "diagnostics": 5,
        "findings": [{"path": 1, "line": "x", "column": None, "code": 3, "message": [], "related": 7}]}).encode(),
    "findings_as_object": lambda root: json.dumps({"format": cache.ENTRY_FORMAT, "key": _key_of(root),
                                                   "findings": {"a": 1}, "diagnostics": []}).encode(),
    "deeply_nested_json": lambda root: b"[" * 100_000,
    "deeply_nested_object": lambda root: b'{"a":' * 100_000,
    "huge_number": lambda root: ('{"format": 1' + "0" * 5000 + "}").encode(),
}


def fresh_report(root: Path):
    return cache.build_report(Path(os.path.abspath(root)), SETTINGS)


@pytest.mark.parametrize("damage", sorted(DAMAGE))
def test_damaged_entry_is_rebuilt(damage: str, workspace: Path) -> None:
    expected = fresh_report(workspace)
    assert cache.load_or_build(workspace, SETTINGS) == expected
    entry = entry_path(workspace)
    assert entry.is_file()
    entry.write_bytes(DAMAGE[damage](workspace))
    assert cache.load_or_build(workspace, SETTINGS) == expected
    assert json.loads(entry.read_text(encoding="utf-8").split("\n", 1)[1])["format"] == cache.ENTRY_FORMAT, \
        "not repaired"


@pytest.mark.parametrize("blocker", ["entry_is_a_folder", "lock_is_a_folder", "cache_dir_is_a_file",
                                     "entry_is_a_symlink_loop"])
def test_cache_paths_taken_by_something_else(blocker: str, workspace: Path) -> None:
    expected = fresh_report(workspace)
    entry = entry_path(workspace)
    if blocker == "cache_dir_is_a_file":
        entry.parent.write_text("not a folder")
    else:
        entry.parent.mkdir()
        if blocker == "entry_is_a_folder":
            entry.mkdir()
        elif blocker == "lock_is_a_folder":
            entry.with_suffix(".lock").mkdir()
        else:
            entry.symlink_to(entry.name)
    assert cache.load_or_build(workspace, SETTINGS) == expected
    assert cache.load_or_build(workspace, SETTINGS) == expected


def test_entry_rewritten_while_it_is_read(workspace: Path) -> None:
    """Another (non-atomic, misbehaving) writer keeps rewriting the entry in pieces during lookups."""
    expected = fresh_report(workspace)
    cache.load_or_build(workspace, SETTINGS)
    entry = entry_path(workspace)
    good = entry.read_bytes()
    stop = threading.Event()

    def scribble() -> None:
        while not stop.is_set():
            for cut in (0, len(good) // 3, len(good) // 2, len(good) - 1, len(good)):
                with entry.open("wb") as handle:
                    handle.write(good[:cut])
                    handle.flush()
                    if cut < len(good):
                        handle.write(b"\x00garbage")

    writer = threading.Thread(target=scribble, daemon=True)
    writer.start()
    try:
        for _ in range(25):
            assert cache.load_or_build(workspace, SETTINGS) == expected
    finally:
        stop.set()
        writer.join(timeout=30)


def _look_up(root: str, barrier, out) -> None:
    barrier.wait()
    try:
        report = cache.load_or_build(Path(root), SETTINGS)
        out.put(("ok", sorted((f.location.path, f.location.line, f.code) for f in report.findings)))
    except BaseException as exc:  # reported to the parent, which fails the test
        out.put(("raised", repr(exc)))


def test_concurrent_first_lookups_agree_and_leave_a_valid_entry(workspace: Path) -> None:
    expected = sorted((f.location.path, f.location.line, f.code) for f in fresh_report(workspace).findings)
    context = multiprocessing.get_context("spawn")
    barrier = context.Barrier(4)
    out = context.Queue()
    workers = [context.Process(target=_look_up, args=(str(workspace), barrier, out)) for _ in range(4)]
    for worker in workers:
        worker.start()
    results = [out.get(timeout=120) for _ in workers]
    for worker in workers:
        worker.join(timeout=120)
    assert results == [("ok", expected)] * 4
    stored = json.loads(entry_path(workspace).read_text(encoding="utf-8").split("\n", 1)[1])
    assert stored["key"] == cache.cache_key(workspace, SETTINGS)
    assert not list(entry_path(workspace).parent.glob(".tmp-*")), "temporary files left behind"


@pytest.mark.skipif(not plugin_available(), reason="flake8_rosgraph.plugin is not written yet (colleague's task)")
@pytest.mark.parametrize("damage", ["garbage", "deeply_nested_json"])
def test_flake8_with_a_damaged_cache(damage: str, workspace: Path) -> None:
    first = flake8_cli(workspace)
    assert_clean_exit(first, allowed=(1,))
    for entry in sorted((workspace / cache.CACHE_DIR_NAME).glob("*.json")):
        entry.write_bytes(DAMAGE[damage](workspace))
    second = flake8_cli(workspace)
    assert_clean_exit(second, allowed=(1,))
    assert second.stdout == first.stdout, second.explain()
    for where, code in GOOD_FLAKE8_FINDINGS:
        assert any(where in line and f" {code} " in line for line in second.stdout.splitlines()), second.explain()
