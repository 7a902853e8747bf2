"""The on-disk workspace cache: keys, invalidation, corruption, concurrency."""
from __future__ import annotations

import json
import multiprocessing
import os
import time
from pathlib import Path

import pytest

from flake8_rosgraph import cache, inventory
from flake8_rosgraph.options import Settings

from .conftest import RAW_STANDARD, analyses

SETTINGS = Settings()


def test_key_is_stable_and_follows_content_and_options(workspace: Path) -> None:
    key = cache.cache_key(workspace, SETTINGS)
    assert cache.cache_key(workspace, SETTINGS) == key
    assert cache.cache_key(workspace, Settings(external_topics=("/orphan",))) != key
    talker = workspace / "src/pkg_a/pkg_a/talker.py"
    talker.write_text(talker.read_text() + "# edited\n")
    edited = cache.cache_key(workspace, SETTINGS)
    assert edited != key
    (workspace / "src/pkg_a/launch").mkdir()
    (workspace / "src/pkg_a/launch/demo.launch.py").write_text("")
    assert cache.cache_key(workspace, SETTINGS) != edited


def test_key_follows_stub_file_content(workspace: Path, tmp_path: Path) -> None:
    stub = tmp_path / "extra.toml"
    stub.write_text("[a]\n")
    settings = Settings(stub_files=(stub,))
    key = cache.cache_key(workspace, settings)
    stub.write_text("[b]\n")
    assert cache.cache_key(workspace, settings) != key


def test_key_ignores_caches_hidden_and_colcon_ignored_folders(workspace: Path) -> None:
    key = cache.cache_key(workspace, SETTINGS)
    for folder in (".rosgraph-cache", ".git", "build", "src/__pycache__"):
        (workspace / folder).mkdir(parents=True, exist_ok=True)
        (workspace / folder / "x.py").write_text("x = 1\n")
    (workspace / "build" / "COLCON_IGNORE").write_text("")
    assert cache.cache_key(workspace, SETTINGS) == key


def _found(report: cache.WorkspaceReport) -> list[tuple[str, int, int, str]]:
    return sorted((f.location.path, f.location.line, f.location.column, f.code) for f in report.findings
                  if f.code in {"ROS001", "ROS002", "ROS003"})


def test_second_lookup_reads_the_cache_and_an_edit_rebuilds(fake_engine: Path, workspace: Path) -> None:
    first = cache.load_or_build(workspace, SETTINGS)
    assert _found(first) == RAW_STANDARD
    assert cache.load_or_build(workspace, SETTINGS) == first
    assert len(analyses(fake_engine)) == 1
    listener = workspace / "src/pkg_b/pkg_b/listener.py"
    listener.write_text(listener.read_text().replace("'nobody'", "'orphan'"))
    rebuilt = cache.load_or_build(workspace, SETTINGS)
    assert len(analyses(fake_engine)) == 2
    assert _found(rebuilt) == [("src/pkg_a/pkg_a/talker.py", 7, 10, "ROS002"),
                               ("src/pkg_b/pkg_b/listener.py", 6, 10, "ROS003")]


def test_related_locations_survive_the_round_trip(fake_engine: Path, workspace: Path) -> None:
    built = cache.load_or_build(workspace, SETTINGS)
    loaded = cache.load_or_build(workspace, SETTINGS)
    loop = [f for f in loaded.findings if f.code == "ROS002"]
    assert loop and loop[0].related[0][0].line == 8
    assert loaded == built


@pytest.mark.parametrize("damage", ["{not json", "[]", '{"format": 1}', ""])
def test_corrupt_entry_is_ignored_and_replaced(fake_engine: Path, workspace: Path, damage: str) -> None:
    cache.load_or_build(workspace, SETTINGS)
    entry = workspace / cache.CACHE_DIR_NAME / f"{cache.cache_key(workspace, SETTINGS)}.json"
    entry.write_text(damage)
    report = cache.load_or_build(workspace, SETTINGS)
    assert _found(report) == RAW_STANDARD
    assert len(analyses(fake_engine)) == 2
    assert json.loads(entry.read_text().split("\n", 1)[1])["format"] == cache.ENTRY_FORMAT


def test_entry_stored_under_another_key_is_not_trusted(fake_engine: Path, workspace: Path) -> None:
    cache.load_or_build(workspace, SETTINGS)
    key = cache.cache_key(workspace, SETTINGS)
    entry = workspace / cache.CACHE_DIR_NAME / f"{key}.json"
    data = json.loads(entry.read_text().split("\n", 1)[1])
    data["key"] = "0" * 64  # stored under another key: signed, so this user's, but not for this key
    entry.write_text(cache.signed_text(data, cache.machine_secret()))
    cache.load_or_build(workspace, SETTINGS)
    assert len(analyses(fake_engine)) == 2


def test_cache_directory_is_marked_and_left_clean(fake_engine: Path, workspace: Path) -> None:
    cache.load_or_build(workspace, SETTINGS)
    folder = workspace / cache.CACHE_DIR_NAME
    assert (folder / ".gitignore").read_text().splitlines()[-1] == "*"
    assert (folder / "COLCON_IGNORE").exists()
    assert (folder / "CACHEDIR.TAG").read_text().startswith("Signature: 8a477f597d28d172789f06886806bc55")
    assert not list(folder.glob(".tmp-*"))


def test_unwritable_cache_location_still_gives_the_findings(fake_engine: Path, workspace: Path,
                                                            tmp_path: Path) -> None:
    blocker = tmp_path / "a-file"
    blocker.write_text("")
    settings = Settings(cache_dir=blocker / "cache")  # cannot be created: its parent is a file
    assert _found(cache.load_or_build(workspace, settings)) == RAW_STANDARD


def test_old_entries_are_pruned(fake_engine: Path, workspace: Path) -> None:
    for n in range(cache.KEEP_ENTRIES + 3):
        cache.load_or_build(workspace, Settings(external_topics=(f"/t{n}",)))
    assert len(list((workspace / cache.CACHE_DIR_NAME).glob("[0-9a-f]*.json"))) == cache.KEEP_ENTRIES


def _worker(root: str, log: str, barrier: multiprocessing.synchronize.Barrier, out: multiprocessing.Queue) -> None:
    os.environ["FAKE_ROSGRAPH_LOG"] = log
    os.environ["FAKE_ROSGRAPH_DELAY"] = "0.5"
    barrier.wait()
    report = cache.load_or_build(Path(root), SETTINGS)
    out.put(_found(report))


def test_concurrent_processes_analyse_once(fake_engine: Path, workspace: Path) -> None:
    context = multiprocessing.get_context("fork")
    barrier = context.Barrier(4)
    out = context.Queue()
    workers = [context.Process(target=_worker, args=(str(workspace), str(fake_engine), barrier, out))
               for _ in range(4)]
    for worker in workers:
        worker.start()
    results = [out.get(timeout=60) for _ in workers]
    for worker in workers:
        worker.join(timeout=60)
    assert results == [RAW_STANDARD] * 4
    assert len(analyses(fake_engine)) == 1


def _settle() -> None:
    """Wait until the files just written are older than the racy window (their change time
    cannot be set back), as files checked out a while ago are."""
    time.sleep(cache.RACY_SECONDS + 0.2)


def test_unchanged_files_are_not_read_again_for_the_key(fake_engine: Path, workspace: Path,
                                                        monkeypatch: pytest.MonkeyPatch) -> None:
    _settle()
    first = cache.load_or_build(workspace, SETTINGS)
    assert (workspace / cache.CACHE_DIR_NAME / cache.INPUT_INDEX).is_file()
    hashed: list[Path] = []
    real = cache._input_digest
    monkeypatch.setattr(cache, "_input_digest", lambda path, root: hashed.append(path) or real(path, root))
    cache.start_run()
    assert cache.load_or_build(workspace, SETTINGS) == first
    assert hashed == [] and len(analyses(fake_engine)) == 1
    # An edit that keeps the size and puts the modification time back still changes ctime.
    listener = workspace / "src/pkg_b/pkg_b/listener.py"
    before = listener.stat()
    listener.write_text(listener.read_text().replace("'nobody'", "'orphan'"))
    os.utime(listener, ns=(before.st_atime_ns, before.st_mtime_ns))
    rebuilt = cache.load_or_build(workspace, SETTINGS)
    assert hashed == [listener] and len(analyses(fake_engine)) == 2
    assert ("src/pkg_b/pkg_b/listener.py", 6, 10, "ROS003") in _found(rebuilt)


def test_one_run_lists_and_keys_the_workspace_once_from_the_lookup_to_the_report(
        fake_engine: Path, workspace: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """flake8 asks whether the report is kept before it forks the child that builds it: the
    child (here: the same process) builds it from that listing and key; the next run lists and
    keys the workspace again, and sees an edit made in between."""
    keyed: list[Path] = []
    listed: list[str] = []
    real_key, real_list = cache.cache_key, inventory._list
    monkeypatch.setattr(cache, "cache_key", lambda root, *a: keyed.append(root) or real_key(root, *a))
    monkeypatch.setattr(inventory, "_list", lambda folder: listed.append(folder) or real_list(folder))
    cache.start_run()
    assert cache.kept_state(workspace, SETTINGS) == "missing"
    folders = sorted(listed)
    first = cache.load_or_build(workspace, SETTINGS)
    assert len(keyed) == 1 and sorted(listed) == folders and len(analyses(fake_engine)) == 1
    assert not any("/nobody_else" in f.message for f in first.findings)

    listener = workspace / "src/pkg_b/pkg_b/listener.py"
    listener.write_text(listener.read_text().replace("'nobody'", "'nobody_else'"))
    cache.start_run()
    assert cache.kept_state(workspace, SETTINGS) == "missing"
    rebuilt = cache.load_or_build(workspace, SETTINGS)
    assert len(keyed) == 2 and sorted(listed) == sorted(folders * 2) and len(analyses(fake_engine)) == 2
    assert any("topic '/nobody_else' has no publisher" in f.message for f in rebuilt.findings)
    cache.start_run()
    assert cache.kept_state(workspace, SETTINGS) == "kept" and len(keyed) == 3


@pytest.mark.parametrize("damage", ["{not json", "[]", '{"format": 1, "files": {}}'])
def test_a_damaged_or_foreign_input_index_only_costs_reading(fake_engine: Path, workspace: Path,
                                                               damage: str) -> None:
    _settle()
    key = cache.cache_key(workspace, SETTINGS)
    cache.load_or_build(workspace, SETTINGS)
    index = workspace / cache.CACHE_DIR_NAME / cache.INPUT_INDEX
    signature, body = index.read_text().split("\n", 1)
    forged = json.loads(body)
    forged["files"] = {rel: [*identity[:4], "0" * 64] for rel, identity in forged["files"].items()}
    for text in (damage, f"{signature}\n{json.dumps(forged)}"):  # a forged digest is not signed by this user
        index.write_text(text)
        cache.start_run()
        assert cache.cache_key(workspace, SETTINGS,
                               cache.InputDigests.load(index.parent, cache.machine_secret())) == key


def test_files_changed_just_now_are_not_remembered(workspace: Path) -> None:
    digests = cache.InputDigests()
    cache.cache_key(workspace, SETTINGS, digests)
    assert digests.seen == {}  # all written a moment ago: their digests could go stale unnoticed
    _settle()
    cache.cache_key(workspace, SETTINGS, digests)
    assert "src/pkg_a/pkg_a/talker.py" in digests.seen
