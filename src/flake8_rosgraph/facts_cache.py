"""The facts of each group of Python modules, kept on disk between runs.

The workspace report (:mod:`.cache`) is keyed by every input, so any edit misses it. Most
of its cost is the Python analysis, and that is done per group of modules that import
nothing from one another (:meth:`.Program.components`): a group nobody edited has the
same facts as last time. They are stored in ``<cache>/groups/<key>.json``, the key a hash
of the tool, the extra stubs and the group's own inputs (its modules' names, paths and
content hashes, the framework classes registered in it, the executables that run it), so
an edit re-analyses the edited module's group only.

Entries are plain JSON (:mod:`.facts_json`), signed like the cache's other entries, written
atomically, and pruned to the most recently used; an unreadable, corrupt or foreign entry
is computed again.
"""
from __future__ import annotations

import contextlib
import hashlib
import os
import stat
import time
from dataclasses import dataclass
from pathlib import Path

from . import facts_json
from .cache import _OWN_FILE, MAX_ENTRY_BYTES, read_signed, tool_fingerprint, write_signed
from .python_facts import PythonFacts
from .safe_io import read_bytes

#: Version of the entry layout; bump it when :mod:`.facts_json` or the facts change shape.
FACTS_FORMAT = 1
GROUPS_DIR = "groups"
#: Entries kept (the most recently used): several states of a large workspace.
KEEP_GROUPS = 4096
#: What the kept entries may take on disk together.
MAX_GROUPS_BYTES = 256 * 1024 * 1024


def groups_dir(cache_dir: Path) -> Path | None:
    """The folder of group entries inside ``cache_dir`` (a folder the cache owns), made if
    missing; ``None`` when it is not a real folder (a link, a file) or cannot be made."""
    folder = cache_dir / GROUPS_DIR
    with contextlib.suppress(FileExistsError, OSError):
        os.mkdir(folder, 0o755)
    try:
        return folder if stat.S_ISDIR(os.lstat(folder).st_mode) else None
    except OSError:
        return None


def context_key(stub_files: tuple[Path, ...]) -> str:
    """What every group's facts depend on besides the group: the tool and the extra stubs."""
    digest = hashlib.sha256(f"rosgraph-facts/{FACTS_FORMAT}\0{tool_fingerprint()}".encode())
    for stub in stub_files:
        try:
            content = hashlib.sha256(read_bytes(Path(stub), None, MAX_ENTRY_BYTES)).hexdigest()
        except OSError as exc:
            content = f"unreadable: {exc.strerror or exc}"
        digest.update(f"\0stub\0{Path(stub).resolve().as_posix()}\0{content}".encode("utf-8", "surrogateescape"))
    return digest.hexdigest()


@dataclass(frozen=True)
class FactsStore:
    """Groups' facts in ``folder``, for :func:`.analysis.build_graph`: read when kept, written
    (with ``store``) when computed."""

    folder: Path
    secret: bytes
    context: str
    store: bool = True

    def read(self, inputs: str) -> PythonFacts | None:
        """The kept facts of the group with these ``inputs``, or ``None``."""
        key = self._key(inputs)
        entry = self.folder / f"{key}.json"
        kept = _read(entry, key, self.secret)
        if kept is not None:
            with contextlib.suppress(OSError):
                os.utime(entry)  # recently used: kept by the pruning
        return kept

    def holds(self, inputs: str) -> bool:
        """Whether an entry is kept for the group with these ``inputs`` (not read: it may still
        be corrupt or foreign, which :meth:`read` finds)."""
        return (self.folder / f"{self._key(inputs)}.json").is_file()

    def write(self, inputs: str, facts: PythonFacts) -> None:
        """Keep the facts computed for the group with these ``inputs`` (safe from several
        processes at once: entries are written atomically)."""
        if not self.store:
            return
        key = self._key(inputs)
        try:
            write_signed(self.folder / f"{key}.json", {"key": key, "facts": facts_json.to_obj(facts)},
                         self.secret)
        except facts_json.NotAFact:
            pass  # a fact the format cannot hold: analysed again next time

    def _key(self, inputs: str) -> str:
        return hashlib.sha256(f"{self.context}\0{inputs}".encode("utf-8", "surrogateescape")).hexdigest()


def _read(entry: Path, key: str, secret: bytes) -> PythonFacts | None:
    obj = read_signed(entry, secret, facts_json.loads_entry)  # hostile facts: None, computed again
    if obj is None or obj.get("key") != key:
        return None  # missing, corrupt, foreign, or not for this key: computed again
    facts = obj.get("facts")
    return facts if isinstance(facts, PythonFacts) else None


def prune(folder: Path) -> None:
    """Keep the most recently used entries, at most :data:`KEEP_GROUPS` and
    :data:`MAX_GROUPS_BYTES`; only ever touches files named like the entries."""
    entries = []
    now = time.time()
    with contextlib.suppress(OSError):
        for item in os.scandir(folder):
            if not _OWN_FILE.match(item.name) or not item.is_file(follow_symlinks=False):
                continue
            with contextlib.suppress(OSError):
                info = item.stat(follow_symlinks=False)
                if not item.name.startswith(".tmp-"):
                    entries.append((info.st_mtime, item.name, info.st_size))
                elif now - info.st_mtime > 3600:  # left by a process that died while writing
                    os.unlink(item.path)
    total = 0
    for count, (_, name, size) in enumerate(sorted(entries, reverse=True)):
        total += size
        if count >= KEEP_GROUPS or total > MAX_GROUPS_BYTES:
            with contextlib.suppress(OSError):
                os.unlink(folder / name)
