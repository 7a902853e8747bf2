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
  setup.cfg, CMakeLists.txt, launch/parameter files, C++ sources and headers,
  ``COLCON_IGNORE`` markers), read with the readers' own rules (:mod:`.safe_io`).
  Any change gives a new key, so a stale entry is never read; old entries are pruned.
* **Reading less**: the digests of the workspace's files are kept by file identity
  (size, times, inode) in ``inputs.json``, signed like the entries; an unchanged
  file is not read again to compute the key (:class:`InputDigests`). The C++ partner
  ends are stored under a key of their own (the C++ files and package folders), so an
  edit to Python code does not parse the C++ tree again (:func:`_cpp_memo`), and the facts of
  each group of Python modules are stored under a key of their own files, so an edit
  re-analyses the edited module's group only (:mod:`.facts_cache`).
* **Concurrency**: a per-key lock file (``fcntl``/``msvcrt`` lock, released by
  the OS if a process dies) makes one process build while the others wait, and
  re-check the cache once they get the lock; entries are written to a
  temporary file and renamed into place, so readers never see half a file.
* **Trust**: entries are signed with a per-user secret (:func:`machine_secret`): a line
  with the HMAC of the JSON text that follows it (:func:`signed_text`),
  so an entry committed to the repository or written elsewhere is ignored; the
  cache only writes into, and prunes, a folder it owns (:func:`_own_dir`), only
  its own files, never through a link. An unreadable, corrupt or foreign entry
  is rebuilt; an unusable cache folder only costs the sharing (each process then
  analyses on its own). The cache holds plain JSON, never pickles.
"""
from __future__ import annotations

import contextlib
import hashlib
import hmac
import json
import os
import re
import secrets
import shutil
import stat
import sys
import tempfile
import time
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING, Any, Callable, Iterator

from . import __version__, inventory
from .cpp import CPP_SUFFIXES
from .escaping import escape_text
from .graph.model import Diagnostic, Location
from .options import Buffers, Settings
from .safe_io import MAX_SOURCE_BYTES, SKIP_DIRS, UnsafeFile, forget_folders, read_bytes
from .findings import Finding, RuleConfig

if TYPE_CHECKING:
    from .workspace import Outlines

CACHE_DIR_NAME = ".rosgraph-cache"
#: Version of the entry layout below; bump it when the layout changes.
ENTRY_FORMAT = 2
#: How long a process waits for another one's analysis before doing its own.
LOCK_TIMEOUT_S = 600.0
#: How many entries (distinct keys) to keep per cache directory.
KEEP_ENTRIES = 16
#: Largest entry written or read: with :data:`KEEP_ENTRIES`, what the cache may take on disk.
MAX_ENTRY_BYTES = 16 * 1024 * 1024

#: Version of the metadata entry (:func:`metadata_key`); bump it when the metadata changes shape.
METADATA_FORMAT = 2
#: The digests of the workspace's inputs from earlier runs (see :class:`InputDigests`).
INPUT_INDEX = "inputs.json"
#: What earlier runs learnt of each Python file without its tree (see :class:`.workspace.Outlines`).
OUTLINES = "outlines.json"
INPUT_INDEX_FORMAT = 1
#: A file modified this recently may change again unnoticed within the clock's resolution.
RACY_SECONDS = 2
#: The only files the cache ever deletes: its entries, their locks, its own unfinished writes.
_OWN_FILE = re.compile(r"^(?:[0-9a-f]{64}\.(?:json|lock)|\.tmp-[A-Za-z0-9_]+\.json)$")
#: Written into a cache folder this tool created (or found empty); its presence marks the folder as ours.
OWNER_MARKER = "CACHEDIR.TAG"
_OWNER_TEXT = "Signature: 8a477f597d28d172789f06886806bc55\n# flake8-rosgraph analysis cache\n"
_MARKERS = {".gitignore": "# created by flake8-rosgraph\n*\n", "COLCON_IGNORE": "", OWNER_MARKER: _OWNER_TEXT}
#: Besides ``*.py``: what the analysis may read (manifests, launch and parameter files, C++ partner ends).
_INPUT_SUFFIXES = frozenset({".py", ".xml", ".yaml", ".yml", ".toml", ".cfg", ".launch",
                             ".msg", ".srv", ".action", ".urdf", ".xacro"}) | CPP_SUFFIXES
#: Files read (or whose presence matters) whatever their suffix.
_INPUT_NAMES = frozenset({"CMakeLists.txt", "COLCON_IGNORE", "AMENT_IGNORE", "CATKIN_IGNORE"})


@dataclass(frozen=True)
class WorkspaceReport:
    """All findings of all rules (off-by-default ones included) and the analysis gaps of one workspace."""

    root: Path
    findings: tuple[Finding, ...]
    diagnostics: tuple[Diagnostic, ...]


# -- the key -------------------------------------------------------------------------------------

def _sha256_file(path: Path) -> str:
    """Content hash of one of the tool's own files (trusted, regular)."""
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _input_digest(path: Path, root: Path | None) -> str:
    """What the key records of an input file: its content hash, or why the analysis does not read it.

    Computed with the readers' own rules (:mod:`.safe_io`), so a FIFO, a device,
    a link out of the workspace or a huge file is never read here either.
    """
    try:
        return hashlib.sha256(read_bytes(path, root, MAX_SOURCE_BYTES)).hexdigest()
    except UnsafeFile as exc:
        try:
            info = os.lstat(path)
            return f"refused:{exc}:{info.st_size}:{info.st_mtime_ns}"
        except OSError:
            return f"refused:{exc}"
    except OSError as exc:
        return f"unreadable:{exc.errno}"


def _encoded(text: str) -> bytes:
    """Key material; file names that are not UTF-8 (surrogate escapes) are encoded as the OS gives them."""
    return text.encode("utf-8", "surrogateescape")


def workspace_inputs(root: Path) -> list[tuple[str, str]]:
    """The workspace files the key covers, as ``(POSIX path relative to root's folder, path)``,
    sorted by the former.

    Every folder any reader enters is walked (only version-control data, build
    products and hidden folders are skipped by all of them), so each file the
    analysis may read is covered; a lone-file root covers that file. Paths stay strings:
    every run walks this, and making a ``Path`` of each file cost more than the walk.
    """
    if not root.is_dir():
        return [(root.name, str(root))] if root.exists() else []
    top = str(root)
    found: list[tuple[str, str]] = []
    for directory, dirnames, filenames in inventory.walk(top):
        dirnames[:] = [d for d in dirnames if not d.startswith(".") and d not in SKIP_DIRS]
        folder = os.path.relpath(directory, top).replace(os.sep, "/")
        prefix = "" if folder == "." else folder + "/"
        # A name without a dot may be a Python program (a shebang, an installed script).
        found += [(prefix + name, os.path.join(directory, name)) for name in filenames
                  if os.path.splitext(name)[1] in _INPUT_SUFFIXES or name in _INPUT_NAMES or "." not in name]
    return sorted(found, key=lambda item: _encoded(item[0]))


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


class InputDigests:
    """Content digests of the workspace's files by file identity, kept between runs.

    Hashing every input on every run costs a warm run more than the cache saves; a file
    whose size, modification and change times and inode are what they were when it was
    hashed has the same content, so its digest is reused. A file changed in the last
    :data:`RACY_SECONDS` could change again within the clock's resolution unnoticed: its
    digest is not remembered. The index is signed like the entries and ignored if not.
    """

    def __init__(self, known: dict[str, list[Any]] | None = None) -> None:
        self.known = known or {}
        self.seen: dict[str, list[Any]] = {}
        #: The digest of every file this run keyed on, by root-relative path.
        self.current: dict[str, str] = {}

    def digest(self, path: str, root: Path, rel: str) -> str:
        try:
            info = os.lstat(path)
        except OSError:
            return _input_digest(Path(path), root)
        identity = [info.st_size, info.st_mtime_ns, info.st_ctime_ns, info.st_ino]
        remembered = self.known.get(rel)
        if isinstance(remembered, list) and len(remembered) == 5 and remembered[:4] == identity \
                and isinstance(remembered[4], str):
            digest = remembered[4]
        else:
            digest = _input_digest(Path(path), root)
        self.current[rel] = digest
        settled = time.time_ns() - max(info.st_mtime_ns, info.st_ctime_ns) > RACY_SECONDS * 1_000_000_000
        if settled and not digest.startswith(("refused:", "unreadable:")):
            self.seen[rel] = identity + [digest]
        return digest

    @classmethod
    def load(cls, cache_dir: Path, secret: bytes) -> InputDigests:
        obj = read_signed(cache_dir / INPUT_INDEX, secret)
        if obj is not None and obj.get("format") == INPUT_INDEX_FORMAT and isinstance(obj.get("files"), dict):
            return cls(obj["files"])
        return cls()  # missing, corrupt or foreign: every input is hashed

    def store(self, cache_dir: Path, secret: bytes) -> None:
        """Write what this run learnt, when it differs from what was read (atomically)."""
        if self.seen != self.known and _own_dir(cache_dir):
            write_signed(cache_dir / INPUT_INDEX, {"format": INPUT_INDEX_FORMAT, "files": self.seen}, secret)


#: The files besides manifests and ignore markers whose content the C++ partner ends depend on.
_CPP_KEY_SUFFIXES = CPP_SUFFIXES | {".msg", ".srv", ".action"}


def _cpp_key(digests: InputDigests) -> str:
    """The key of the C++ partner ends: the C++ files, the folders that make packages, and the
    interface files (a package's own ``msg/Status.msg`` names its C++ ``msg::Status``)."""
    from .cpp import memo as cpp_memo  # imported here: a warm run never needs the C++ front end
    from .workspace import IGNORE_MARKERS

    digest = hashlib.sha256(f"rosgraph-cpp/{cpp_memo.MEMO_FORMAT}\0{tool_fingerprint()}\0"
                            f"{_parser_versions()}".encode())
    for rel in sorted(digests.current, key=_encoded):
        name = rel.rsplit("/", 1)[-1]
        if os.path.splitext(name)[1] in _CPP_KEY_SUFFIXES or name == "package.xml" or name in IGNORE_MARKERS:
            digest.update(_encoded(f"\0{rel}\0{digests.current[rel]}"))
    return digest.hexdigest()


@lru_cache(maxsize=1)
def _parser_versions() -> str:
    """The C++ parser's versions (its grammar decides what is read): the names of the
    distributions' metadata folders beside the modules, found without importing them
    (``importlib.metadata`` scans every ``sys.path`` entry: a tenth of a second per run);
    for another kind of install, the module file's size and time."""
    import importlib.util

    versions = []
    for module in ("tree_sitter", "tree_sitter_cpp"):
        spec = importlib.util.find_spec(module)
        if spec is None or not spec.origin:
            versions.append(f"{module}=none")
            continue
        origin = Path(spec.origin)
        found = sorted(p.name for p in origin.parent.parent.glob(f"{module}-*.dist-info"))
        if not found:
            info = origin.stat()
            found = [f"{info.st_size}:{info.st_mtime_ns}"]
        versions.append(f"{module}={','.join(found)}")
    return ",".join(versions)


def _cpp_memo(cache_dir: Path, secret: bytes, key: str) -> Callable:
    """A memo for :func:`.analysis.build_graph`: the C++ ends stored under ``key``, or read and stored."""
    from .cpp import memo as cpp_memo

    return _json_memo(cache_dir, secret, key, "ends", lambda found: cpp_memo.to_obj(*found), cpp_memo.from_obj)


def metadata_key(digests: InputDigests) -> str:
    """The key of the workspace's metadata (:mod:`.metadata`): every input but the content of
    Python modules — their paths count (a script's presence), and ``setup.py`` is metadata."""
    digest = hashlib.sha256(f"rosgraph-metadata/{METADATA_FORMAT}\0{tool_fingerprint()}".encode())
    for rel in sorted(digests.current, key=_encoded):
        name = rel.rsplit("/", 1)[-1]
        content = digests.current[rel] if not name.endswith(".py") or name == "setup.py" else ""
        digest.update(_encoded(f"\0{rel}\0{content}"))
    return digest.hexdigest()


def _metadata_memo(cache_dir: Path, secret: bytes, key: str) -> Callable:
    """A memo for :func:`.analysis.build_graph`: the workspace's metadata stored under ``key``, or read and stored."""
    from . import facts_json
    from .metadata import WorkspaceMetadata

    def decode(obj: Any) -> Any:
        metadata = facts_json.from_obj(obj)
        if not isinstance(metadata, WorkspaceMetadata):
            raise ValueError("not the workspace's metadata")
        return metadata

    return _json_memo(cache_dir, secret, key, "metadata", facts_json.to_obj, decode)


def _json_memo(cache_dir: Path, secret: bytes, key: str, name: str,
               encode: Callable[[Any], Any], decode: Callable[[Any], Any]) -> Callable:
    """A memo of what ``read`` returns, stored as ``name`` in the signed entry ``<key>.json``:
    read back when the entry is this user's and whole, else read anew and stored (when
    ``encode`` can say it: a :class:`ValueError` there only costs the storing)."""
    entry = cache_dir / f"{key}.json"

    def memo(read: Callable[[], Any]) -> Any:
        obj = read_signed(entry, secret)
        if obj is not None and obj.get("key") == key:
            try:
                kept = decode(obj[name])
            except (ValueError, KeyError, TypeError, RecursionError):
                pass  # corrupt: read the sources
            else:
                with contextlib.suppress(OSError):
                    os.utime(entry)  # recently used: the pruning keeps it
                return kept
        found = read()
        try:
            obj = {"key": key, name: encode(found)}
        except ValueError:
            return found  # a value the format cannot hold: read again next time
        if _own_dir(cache_dir):
            write_signed(entry, obj, secret)
        return found

    return memo


def cache_key(root: Path, settings: Settings, digests: InputDigests | None = None) -> str:
    """The key of the analysis of ``root`` under ``settings`` (see module docstring); ``digests``
    spares reading the files that did not change since they were hashed."""
    digest = hashlib.sha256(f"rosgraph-cache/{ENTRY_FORMAT}\0{tool_fingerprint()}".encode())
    for stub in settings.stub_files:
        digest.update(_encoded(f"\0stub\0{stub.resolve().as_posix()}\0{_input_digest(stub, None)}"))
    for name in settings.external_topics:
        digest.update(_encoded(f"\0external\0{name}"))
    for folder in settings.interface_dirs:
        for _, name in workspace_inputs(folder) if folder.is_dir() else ():
            path = Path(name)
            digest.update(_encoded(f"\0interface\0{path.resolve().as_posix()}\0{_input_digest(path, None)}"))
    digests = digests or InputDigests()
    for rel, path in workspace_inputs(root):
        digest.update(_encoded(f"\0file\0{rel}\0{digests.digest(path, root, rel)}"))
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


# -- trust: a per-machine secret signs every entry ------------------------------------------------

def _key_file() -> Path:
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base, "flake8-rosgraph", "key")


def _read_secret(path: Path) -> bytes:
    """The secret at ``path``: a regular file of ours, private, not a link (``OSError`` otherwise)."""
    fd = os.open(path, os.O_RDONLY | getattr(os, "O_NOFOLLOW", 0) | getattr(os, "O_NONBLOCK", 0))
    try:
        info = os.fstat(fd)
        ours = not hasattr(os, "getuid") or info.st_uid == os.getuid()
        private = os.name == "nt" or not info.st_mode & 0o077
        if not (stat.S_ISREG(info.st_mode) and ours and private):
            raise OSError(f"{path} is not a private file of this user")
        data = os.read(fd, 4096).strip()
    finally:
        os.close(fd)
    if len(data) < 32:
        raise OSError(f"{path} holds no usable key")
    return data


@lru_cache(maxsize=1)
def machine_secret() -> bytes | None:
    """This user's cache-signing secret (``~/.cache/flake8-rosgraph/key``, created 0600); ``None`` if unavailable.

    Entries are signed with it, so an entry committed to a repository or written
    by another user or machine is never trusted: its signature cannot be forged
    without the secret, and without a secret no entry is read or written at all.
    """
    path = _key_file()
    try:
        return _read_secret(path)
    except FileNotFoundError:
        pass
    except OSError:
        return None
    try:
        path.parent.mkdir(mode=0o700, parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=".key-", dir=path.parent)  # created 0600
        try:
            os.write(fd, secrets.token_hex(32).encode())
            os.close(fd)
            try:
                os.link(tmp, path)  # never replaces a secret another process created meanwhile
            except FileExistsError:
                pass
        finally:
            os.unlink(tmp)
        return _read_secret(path)
    except OSError:
        return None


def _signature(secret: bytes, body: bytes) -> bytes:
    """HMAC of an entry's JSON text, as hex digits."""
    return hmac.new(secret, body, hashlib.sha256).hexdigest().encode("ascii")


def signed_text(obj: dict[str, Any], secret: bytes) -> str:
    """What :func:`write_signed` stores: a line with the signature, then ``obj``'s JSON text.

    The signature covers the text exactly as stored, so a reader checks it before it parses
    anything, and never re-encodes what it read to check it (that cost every read as much as
    the parsing)."""
    body = json.dumps(obj, sort_keys=True, ensure_ascii=True, separators=(",", ":"))
    return f"{_signature(secret, body.encode('ascii')).decode('ascii')}\n{body}"


def read_signed(path: Path, secret: bytes) -> dict[str, Any] | None:
    """The JSON object stored at ``path`` when this user's secret signed it; ``None`` when it is
    missing, unreadable, corrupt, too big or written by anyone else (untrusted)."""
    try:
        data = read_bytes(path, path.parent, MAX_ENTRY_BYTES)
    except OSError:
        return None
    signature, newline, body = data.partition(b"\n")
    if not newline or not hmac.compare_digest(signature, _signature(secret, body)):
        return None
    try:
        obj = json.loads(body.decode("ascii"))
    except (ValueError, RecursionError):
        return None
    return obj if isinstance(obj, dict) else None


def write_signed(path: Path, obj: dict[str, Any], secret: bytes) -> None:
    """Sign ``obj`` and write it to ``path`` atomically (the caller has checked that the cache
    owns the folder); an object larger than :data:`MAX_ENTRY_BYTES` is not written (the cache
    stays bounded on disk), and a failed write only costs the keeping."""
    text = signed_text(obj, secret)
    if len(text) <= MAX_ENTRY_BYTES:
        with contextlib.suppress(OSError):
            _replace_with(path, text)


# -- the cache folder: only ever one this tool owns -----------------------------------------------

def _own_dir(cache_dir: Path) -> bool:
    """Create ``cache_dir`` or adopt it when empty; true only for a real folder marked as this tool's.

    A folder someone else made (``--cache-dir .``, ``--cache-dir ~/src``) is never
    written into: the markers (``.gitignore``: ``*``, ``COLCON_IGNORE``) would hide
    the user's files from git and colcon, and pruning would delete theirs.
    """
    try:
        info = os.lstat(cache_dir)
    except FileNotFoundError:
        _create_marked(cache_dir)
        try:
            info = os.lstat(cache_dir)
        except OSError:
            return False
    except OSError:
        return False
    if not stat.S_ISDIR(info.st_mode):  # a link (maybe dangling) or a file: not ours
        return False
    marker = cache_dir / OWNER_MARKER
    try:
        if read_bytes(marker, cache_dir, 4096).decode("utf-8", "replace") == _OWNER_TEXT:
            return True
    except OSError:
        pass
    try:
        if any(os.scandir(cache_dir)):
            return False
    except OSError:
        return False
    try:
        for name, content in _MARKERS.items():
            _create_new(cache_dir / name, content.encode())
    except OSError:
        return False
    return True


def _create_marked(cache_dir: Path) -> None:
    """Create ``cache_dir`` with its markers in one step, so no other process sees it half made.

    flake8's workers start together: the folder is assembled under a hidden
    temporary name and renamed into place; whoever loses the race drops its copy
    and adopts the winner's.
    """
    try:
        cache_dir.parent.mkdir(parents=True, exist_ok=True)
        staging = Path(tempfile.mkdtemp(prefix=".rosgraph-cache-new-", dir=cache_dir.parent))
    except OSError:
        return
    try:
        for name, content in _MARKERS.items():
            _create_new(staging / name, content.encode())
        os.rename(staging, cache_dir)
    except OSError:
        shutil.rmtree(staging, ignore_errors=True)


def _create_new(path: Path, content: bytes) -> None:
    """Write a new file; fails rather than follow a link or overwrite anything already there."""
    fd = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_NOFOLLOW", 0), 0o644)
    try:
        os.write(fd, content)
    finally:
        os.close(fd)


def _read_entry(entry: Path, root: Path, key: str, secret: bytes) -> WorkspaceReport | None:
    obj = read_signed(entry, secret)
    if obj is None:
        return None  # missing, corrupt or not written by this user on this machine: rebuilt
    try:
        return report_from_obj(obj, root, key)
    except (ValueError, KeyError, TypeError, RecursionError):
        return None  # hostile: rebuilt


def _write_entry(entry: Path, report: WorkspaceReport, key: str, secret: bytes) -> None:
    write_signed(entry, report_to_obj(report, key), secret)  # too big: kept in memory only


def _replace_with(target: Path, text: str) -> None:
    """Write ``text`` to a temporary file beside ``target`` and rename it over ``target``."""
    fd, tmp = tempfile.mkstemp(prefix=".tmp-", suffix=".json", dir=target.parent)
    try:
        with os.fdopen(fd, "w", encoding="ascii") as handle:
            handle.write(text)
        os.chmod(tmp, 0o644)  # mkstemp makes it private; the workspace's other users share the cache
        os.replace(tmp, target)  # replaces a link at ``target`` itself, never writes through it
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise


def _prune(cache_dir: Path) -> None:
    """Keep the newest :data:`KEEP_ENTRIES` entries; only ever touches files named like the cache's own."""
    now = time.time()
    entries: list[tuple[float, str]] = []
    for item in os.scandir(cache_dir):
        if not _OWN_FILE.match(item.name) or not item.is_file(follow_symlinks=False):
            continue
        mtime = item.stat(follow_symlinks=False).st_mtime
        if item.name.startswith(".tmp-"):
            if now - mtime > 3600:  # left by a process that died while writing
                with contextlib.suppress(OSError):
                    os.unlink(item.path)
        elif item.name.endswith(".json"):
            entries.append((mtime, item.name))
    for _, name in sorted(entries, reverse=True)[KEEP_ENTRIES:]:
        for stale in (name, name[:-len(".json")] + ".lock"):
            with contextlib.suppress(OSError):
                os.unlink(cache_dir / stale)


@contextlib.contextmanager
def exclusive_lock(lock_path: Path, timeout: float = LOCK_TIMEOUT_S) -> Iterator[bool]:
    """Hold an exclusive lock on ``lock_path``; yields ``False`` if it could not be had in time."""
    fd = os.open(lock_path, os.O_RDWR | os.O_CREAT | getattr(os, "O_NOFOLLOW", 0)
                 | getattr(os, "O_NONBLOCK", 0), 0o644)
    handle = os.fdopen(fd, "r+b")
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

def build_report(root: Path, settings: Settings, buffers: Buffers = (),
                 cpp_ends: Callable | None = None, groups: Callable | None = None,
                 metadata: Callable | None = None, outlines: Outlines | None = None) -> WorkspaceReport:
    """Analyse ``root`` and run every rule, uncached but for the C++ ends (``cpp_ends``, see
    :func:`_cpp_memo`), the facts of groups of Python modules (``groups``, see
    :mod:`.facts_cache`) and the metadata (``metadata``, see :func:`_metadata_memo`); imports
    the heavy parts only when needed."""
    from .analysis import build_graph
    from .rules import RULES, run_rules

    from .launch.api import judged_graph

    graph = build_graph(root, tuple(settings.stub_files), settings.interface_dirs, buffers, cpp_ends,
                        groups, metadata, outlines)
    config = RuleConfig(external_names=frozenset(settings.external_topics))
    # Judged as launched: a topic connected after remapping is connected.
    findings = run_rules(judged_graph(graph, graph.systems), config,
                         select=[rule.code for rule in RULES])
    # Messages quote names from the analysed code: escaped here, so every front end prints them safely.
    safe = {Finding(f.location, f.code, escape_text(f.message),
                    tuple((loc, escape_text(label)) for loc, label in f.related)) for f in findings}
    return WorkspaceReport(root, tuple(sorted(safe)), tuple(sorted(set(graph.diagnostics))))


def load_or_build(root: Path, settings: Settings, build: bool = True) -> WorkspaceReport | None:
    """The report for ``root``: from the cache when a valid entry exists, else built and stored
    (without ``build``: ``None`` instead).

    The disk cache is used only with this user's signing secret and in a folder
    the tool owns (see :func:`_own_dir`); otherwise each run analyses afresh,
    which is slower but never wrong.
    """
    root = Path(os.path.abspath(root))
    keyed = _KEYED.pop((root, settings), None)
    # the key and the analysis read one listing of the workspace
    with inventory.shared(root, keyed.listing if keyed is not None else None) as listing:
        return _load_or_build(root, settings, build, keyed or _Keyed(listing))


@dataclass
class _Keyed:
    """A workspace's listing for one run and, once worked out, its cache key with the digests
    it was made from. :func:`kept_state` leaves it for the same run's :func:`load_or_build`
    (in flake8's process, or in the child flake8 forks to analyse, which inherits it): the
    workspace is listed and keyed once per run."""

    listing: inventory.Inventory
    key: str | None = None
    digests: InputDigests | None = None


#: Keys :func:`kept_state` worked out for a report it did not find, until the run builds it.
_KEYED: dict[tuple[Path, Settings], _Keyed] = {}


def _load_or_build(root: Path, settings: Settings, build: bool, keyed: _Keyed) -> WorkspaceReport | None:
    secret = machine_secret()
    cache_dir = _cache_dir(root, settings)
    if secret is None or cache_dir is None:
        return build_report(root, settings) if build else None
    if keyed.key is None or keyed.digests is None:
        keyed.digests = InputDigests.load(cache_dir, secret)
        keyed.key = cache_key(root, settings, keyed.digests)
        keyed.digests.store(cache_dir, secret)
    key, digests = keyed.key, keyed.digests
    entry = cache_dir / f"{key}.json"
    cached = _read_entry(entry, root, key, secret)
    if cached is None and not build:
        _KEYED[(root, settings)] = keyed  # the run builds it next: keyed already
    if cached is not None or not build:
        return cached  # the common case: nothing else to key, import or read
    with contextlib.ExitStack() as stack:
        locked = False
        if _own_dir(entry.parent):
            try:
                locked = stack.enter_context(exclusive_lock(entry.with_suffix(".lock")))
            except OSError:  # read-only workspace: no sharing, still correct
                locked = False
        if locked:  # whoever held the lock before us may have stored the entry meanwhile
            cached = _read_entry(entry, root, key, secret)
            if cached is not None:
                return cached
        from . import facts_cache
        cpp_ends = _cpp_memo(cache_dir, secret, _cpp_key(digests))
        metadata = _metadata_memo(cache_dir, secret, metadata_key(digests))
        folder = facts_cache.groups_dir(cache_dir) if _own_dir(cache_dir) else None
        groups = None if folder is None else \
            facts_cache.FactsStore(folder, secret, facts_cache.context_key(tuple(settings.stub_files)))
        from .workspace import Outlines
        outlines = Outlines(_read_outlines(cache_dir, secret), digests.current) if groups is not None else None
        report = build_report(root, settings, cpp_ends=cpp_ends, groups=groups, metadata=metadata,
                              outlines=outlines)
        if locked:
            with contextlib.suppress(OSError):
                _write_entry(entry, report, key, secret)
                _prune(entry.parent)
            if outlines is not None and outlines.used != outlines.known:
                # this run's files only: the index stays the workspace's size
                write_signed(cache_dir / OUTLINES, {"context": tool_fingerprint(), "files": outlines.used}, secret)
            if folder is not None:
                facts_cache.prune(folder)
        return report


def kept_state(root: Path, settings: Settings) -> str:
    """Whether the cache keeps the report of ``root``: ``"kept"`` (then it is remembered for
    this run, see :func:`workspace_report`), ``"missing"`` (another process may build it for
    this one), or ``"uncacheable"`` (no secret, or no folder the tool owns)."""
    root = Path(os.path.abspath(root))
    cache_dir = _cache_dir(root, settings)
    if machine_secret() is None or cache_dir is None or not _own_dir(cache_dir):
        return "uncacheable"
    kept = load_or_build(root, settings, build=False)
    if kept is None:
        return "missing"
    _MEMO[(root, settings, ())] = kept
    return "kept"


def _read_outlines(cache_dir: Path, secret: bytes) -> dict[str, Any]:
    """The Python files' outlines earlier runs stored (:class:`.workspace.Outlines`), if trusted."""
    obj = read_signed(cache_dir / OUTLINES, secret)
    if obj is not None and obj.get("context") == tool_fingerprint() and isinstance(obj.get("files"), dict):
        return obj["files"]
    return {}  # missing, corrupt or foreign: every file is parsed


def _cache_dir(root: Path, settings: Settings) -> Path | None:
    """Where the cache of ``root`` lives (absolute); ``None`` for a lone file without ``--cache-dir``."""
    cache_dir = settings.cache_dir or (root / CACHE_DIR_NAME if root.is_dir() else None)
    return None if cache_dir is None else Path(os.path.abspath(cache_dir))


def _unsaved_report(root: Path, settings: Settings, buffers: Buffers) -> WorkspaceReport:
    """The report with an editor's unsaved ``buffers``: never stored, but the groups of modules
    the buffers do not touch are read from the cache when it has them."""
    from . import facts_cache
    secret = machine_secret()
    cache_dir = _cache_dir(root, settings)
    folder = cache_dir / facts_cache.GROUPS_DIR if secret is not None and cache_dir is not None else None
    if folder is None or not folder.is_dir() or folder.is_symlink():
        return build_report(root, settings, buffers)
    context = facts_cache.context_key(tuple(settings.stub_files))
    return build_report(root, settings, buffers,
                        groups=facts_cache.FactsStore(folder, secret, context, store=False))


#: Per-process results, so that the many files of one run share one lookup.
_MEMO: dict[tuple[Path, Settings, Buffers], WorkspaceReport] = {}


def workspace_report(root: Path, settings: Settings, buffers: Buffers = ()) -> WorkspaceReport:
    """:func:`load_or_build`, memoised for the life of the current run (see :func:`start_run`).

    With ``buffers`` (an editor's unsaved content) the analysis is never cached on
    disk: a buffer changes with every keystroke and is nobody else's business.
    """
    memo_key = (Path(os.path.abspath(root)), settings, buffers)
    if memo_key not in _MEMO:
        _MEMO[memo_key] = (_unsaved_report(memo_key[0], settings, buffers) if buffers
                           else load_or_build(memo_key[0], settings))
    return _MEMO[memo_key]


def start_run() -> None:
    """Forget memoised reports and resolved folders: a new flake8 run must see the files as they are now."""
    _MEMO.clear()
    _KEYED.clear()
    forget_folders()
