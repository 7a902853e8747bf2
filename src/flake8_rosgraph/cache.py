"""The workspace analysis, run once per flake8 run and shared through an on-disk cache.

flake8 creates one checker per file, possibly in worker processes started by
fork, spawn or forkserver, while the graph rules need the whole workspace. So
the first process that needs the findings analyses the workspace and stores
them in ``<root>/.rosgraph-cache/<key>.json``; every other process (and every
later run on unchanged code) reads that file.

* **Key**: a hash of the tool (version, Python ``major.minor``, the package's own
  sources and built-in stubs), the extra stub files' contents, the options that
  change findings (external topics) and the path and content hash of every
  workspace file the analysis may read (``.py`` plus ROS metadata: package.xml,
  setup.cfg, launch/parameter files, C++ sources and headers). Any change gives a
  new key, so a stale entry is never read; old entries are pruned.
* **Concurrency**: a per-key lock file (``fcntl``/``msvcrt`` lock, released by
  the OS if a process dies) makes one process build while the others wait, and
  re-check the cache once they get the lock; entries are written to a
  temporary file and renamed into place, so readers never see half a file.
* **Robustness**: an unreadable, corrupt or foreign entry is ignored and
  rebuilt; an unwritable cache directory only costs the sharing (each process
  then analyses on its own). The cache holds plain JSON, never pickles, so a
  tampered cache cannot run code.
"""
from __future__ import annotations

import contextlib
import hashlib
import json
import os
import stat
import sys
import tempfile
import time
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Any, Iterator

from . import __version__
from .cpp import CPP_SUFFIXES
from .graph.model import Diagnostic, Location
from .options import Settings
from .findings import Finding, RuleConfig

CACHE_DIR_NAME = ".rosgraph-cache"
#: Version of the entry layout below; bump it when the layout changes.
ENTRY_FORMAT = 1
#: How long a process waits for another one's analysis before doing its own.
LOCK_TIMEOUT_S = 600.0
#: How many entries (distinct keys) to keep per cache directory.
KEEP_ENTRIES = 16

#: Directories that never hold workspace sources.
_SKIP_DIRS = frozenset({"__pycache__", "node_modules"})
#: Files in a directory that tell ROS tools to skip it.
_IGNORE_MARKERS = ("COLCON_IGNORE", "AMENT_IGNORE", "CATKIN_IGNORE")
#: Besides ``*.py``: what the analysis may read (manifests, launch and parameter files, C++ partner ends).
_INPUT_SUFFIXES = frozenset({".py", ".xml", ".yaml", ".yml", ".toml", ".cfg", ".launch"}) | CPP_SUFFIXES


@dataclass(frozen=True)
class WorkspaceReport:
    """All findings of all rules (off-by-default ones included) and the analysis gaps of one workspace."""

    root: Path
    findings: tuple[Finding, ...]
    diagnostics: tuple[Diagnostic, ...]


# -- the key -------------------------------------------------------------------------------------

def _sha256_file(path: Path) -> str:
    """Content hash of a regular file; FIFOs and devices (which never end) hash as such."""
    info = path.stat()
    if not stat.S_ISREG(info.st_mode):
        return f"special:{stat.S_IFMT(info.st_mode)}"
    digest = hashlib.sha256()
    with path.open("rb") as handle:
        for block in iter(lambda: handle.read(1 << 16), b""):
            digest.update(block)
    return digest.hexdigest()


def workspace_inputs(root: Path) -> list[Path]:
    """The workspace files the key covers, sorted by POSIX path relative to ``root``."""
    found: list[Path] = []
    for directory, dirnames, filenames in os.walk(root):
        if directory != str(root) and any(m in filenames for m in _IGNORE_MARKERS + ("pyvenv.cfg",)):
            dirnames[:] = []
            continue
        dirnames[:] = [d for d in dirnames if not d.startswith(".") and d not in _SKIP_DIRS]
        found += [Path(directory, name) for name in filenames if Path(name).suffix in _INPUT_SUFFIXES]
    return sorted(found, key=lambda p: p.relative_to(root).as_posix())


@lru_cache(maxsize=1)
def tool_fingerprint() -> str:
    """Hash of what makes this tool produce what it produces; editing the tool's code changes it."""
    from . import stubs

    digest = hashlib.sha256(f"{__version__}\0{sys.version_info[0]}.{sys.version_info[1]}".encode())
    package_dir = Path(__file__).resolve().parent
    sources = sorted(package_dir.rglob("*.py")) + sorted(Path(stubs.__file__).resolve().parent.glob("*.toml"))
    for path in sources:
        digest.update(f"\0{path.name}\0{_sha256_file(path)}".encode())
    return digest.hexdigest()


def cache_key(root: Path, settings: Settings) -> str:
    """The key of the analysis of ``root`` under ``settings`` (see module docstring)."""
    digest = hashlib.sha256(f"rosgraph-cache/{ENTRY_FORMAT}\0{tool_fingerprint()}".encode())
    for stub in settings.stub_files:
        content = _sha256_file(stub) if stub.is_file() else "missing"
        digest.update(f"\0stub\0{stub.resolve().as_posix()}\0{content}".encode())
    for name in settings.external_topics:
        digest.update(f"\0external\0{name}".encode())
    for path in workspace_inputs(root):
        try:
            content = _sha256_file(path)
        except OSError:
            content = "unreadable"
        digest.update(f"\0file\0{path.relative_to(root).as_posix()}\0{content}".encode())
    return digest.hexdigest()


# -- entries -------------------------------------------------------------------------------------

def _location_obj(location: Location) -> dict[str, Any]:
    return {"path": location.path, "line": location.line, "column": location.column}


def _location(obj: dict[str, Any]) -> Location:
    path, line, column = obj["path"], obj["line"], obj["column"]
    if not (isinstance(path, str) and isinstance(line, int) and isinstance(column, int)):
        raise ValueError("bad location")
    return Location(path, line, column)


def _text(value: Any) -> str:
    if not isinstance(value, str):
        raise ValueError("expected a string")
    return value


def report_to_obj(report: WorkspaceReport, key: str) -> dict[str, Any]:
    """The JSON form of a report, as stored in the cache."""
    return {
        "format": ENTRY_FORMAT,
        "key": key,
        "findings": [
            {**_location_obj(f.location), "code": f.code, "message": f.message,
             "related": [{**_location_obj(loc), "label": label} for loc, label in f.related]}
            for f in report.findings
        ],
        "diagnostics": [
            {"path": d.path, "line": d.line, "message": d.message, "severity": d.severity}
            for d in report.diagnostics
        ],
    }


def report_from_obj(obj: Any, root: Path, key: str) -> WorkspaceReport:
    """Parse a stored entry; ``ValueError``/``KeyError``/``TypeError`` when it is not a valid one for ``key``."""
    if not isinstance(obj, dict) or obj.get("format") != ENTRY_FORMAT or obj.get("key") != key:
        raise ValueError("not an entry for this key")
    findings = tuple(
        Finding(_location(f), _text(f["code"]), _text(f["message"]),
                tuple((_location(r), _text(r["label"])) for r in f["related"]))
        for f in obj["findings"]
    )
    diagnostics = tuple(
        Diagnostic(_text(d["path"]), d["line"], _text(d["message"]), _text(d["severity"]))
        for d in obj["diagnostics"]
    )
    return WorkspaceReport(root, findings, diagnostics)


def _read_entry(entry: Path, root: Path, key: str) -> WorkspaceReport | None:
    try:
        return report_from_obj(json.loads(entry.read_text(encoding="utf-8")), root, key)
    except (OSError, ValueError, KeyError, TypeError, RecursionError):
        return None  # unreadable, corrupt or hostile: rebuilt


def _write_entry(entry: Path, report: WorkspaceReport, key: str) -> None:
    text = json.dumps(report_to_obj(report, key), indent=1, sort_keys=True)
    fd, tmp = tempfile.mkstemp(prefix=".tmp-", suffix=".json", dir=entry.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as handle:
            handle.write(text)
        os.chmod(tmp, 0o644)  # mkstemp makes it private; the workspace's other users share the cache
        os.replace(tmp, entry)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise


def _prepare_dir(cache_dir: Path) -> None:
    """Create the cache directory, marked so that git, colcon and backup tools leave it alone."""
    cache_dir.mkdir(parents=True, exist_ok=True)
    markers = {
        ".gitignore": "# created by flake8-rosgraph\n*\n",
        "COLCON_IGNORE": "",
        "CACHEDIR.TAG": "Signature: 8a477f597d28d172789f06886806bc55\n# flake8-rosgraph analysis cache\n",
    }
    for name, content in markers.items():
        marker = cache_dir / name
        if not marker.exists():
            marker.write_text(content, encoding="utf-8")


def _prune(cache_dir: Path) -> None:
    entries = sorted(cache_dir.glob("*.json"), key=lambda p: (p.stat().st_mtime, p.name), reverse=True)
    for stale in entries[KEEP_ENTRIES:]:
        with contextlib.suppress(OSError):
            stale.unlink()
            stale.with_suffix(".lock").unlink()


@contextlib.contextmanager
def exclusive_lock(lock_path: Path, timeout: float = LOCK_TIMEOUT_S) -> Iterator[bool]:
    """Hold an exclusive lock on ``lock_path``; yields ``False`` if it could not be had in time."""
    handle = open(lock_path, "a+b")
    try:
        deadline = time.monotonic() + timeout
        delay = 0.01
        while not _try_lock(handle):
            if time.monotonic() >= deadline:
                yield False
                return
            time.sleep(delay)
            delay = min(delay * 2, 0.2)
        try:
            yield True
        finally:
            _unlock(handle)
    finally:
        handle.close()


if os.name == "nt":  # pragma: no cover - exercised on Windows only
    import msvcrt

    def _try_lock(handle: Any) -> bool:
        try:
            handle.seek(0)
            msvcrt.locking(handle.fileno(), msvcrt.LK_NBLCK, 1)
            return True
        except OSError:
            return False

    def _unlock(handle: Any) -> None:
        handle.seek(0)
        msvcrt.locking(handle.fileno(), msvcrt.LK_UNLCK, 1)
else:
    import fcntl

    def _try_lock(handle: Any) -> bool:
        try:
            fcntl.flock(handle.fileno(), fcntl.LOCK_EX | fcntl.LOCK_NB)
            return True
        except OSError:
            return False

    def _unlock(handle: Any) -> None:
        fcntl.flock(handle.fileno(), fcntl.LOCK_UN)


# -- the analysis ----------------------------------------------------------------------------

def build_report(root: Path, settings: Settings) -> WorkspaceReport:
    """Analyse ``root`` and run every rule, uncached (imports the heavy parts only when needed)."""
    from .analysis import build_graph
    from .rules import RULES, run_rules

    from .launch.api import judged_graph

    graph = build_graph(root, tuple(settings.stub_files))
    config = RuleConfig(external_names=frozenset(settings.external_topics))
    # Judged as launched: a topic connected after remapping is connected.
    findings = run_rules(judged_graph(graph, graph.systems), config,
                         select=[rule.code for rule in RULES])
    return WorkspaceReport(root, tuple(sorted(set(findings))), tuple(sorted(set(graph.diagnostics))))


def load_or_build(root: Path, settings: Settings) -> WorkspaceReport:
    """The report for ``root``: from the cache when a valid entry exists, else built and stored."""
    root = Path(os.path.abspath(root))
    key = cache_key(root, settings)
    cache_dir = settings.cache_dir or root / CACHE_DIR_NAME
    entry = cache_dir / f"{key}.json"
    cached = _read_entry(entry, root, key)
    if cached is not None:
        return cached
    with contextlib.ExitStack() as stack:
        try:
            _prepare_dir(cache_dir)
            locked = stack.enter_context(exclusive_lock(entry.with_suffix(".lock")))
        except OSError:  # read-only workspace: no sharing, still correct
            locked = False
        if locked:  # whoever held the lock before us may have stored the entry meanwhile
            cached = _read_entry(entry, root, key)
            if cached is not None:
                return cached
        report = build_report(root, settings)
        if locked:
            with contextlib.suppress(OSError):
                _write_entry(entry, report, key)
                _prune(cache_dir)
        return report


#: Per-process results, so that the many files of one run share one lookup.
_MEMO: dict[tuple[Path, Settings], WorkspaceReport] = {}


def workspace_report(root: Path, settings: Settings) -> WorkspaceReport:
    """:func:`load_or_build`, memoised for the life of the current run (see :func:`start_run`)."""
    memo_key = (Path(os.path.abspath(root)), settings)
    if memo_key not in _MEMO:
        _MEMO[memo_key] = load_or_build(memo_key[0], settings)
    return _MEMO[memo_key]


def start_run() -> None:
    """Forget memoised reports: a new flake8 run must see the files as they are now."""
    _MEMO.clear()
