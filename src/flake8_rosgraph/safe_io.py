"""The one way every reader opens a workspace file: regular files inside the workspace, bounded.

A pull request can add any file under any name: a FIFO called ``package.xml``
(opening it for reading blocks until a writer comes), a link to ``/dev/zero``
(reads never end), a link to ``~/.aws/credentials`` (its content would reach
the output through a parse error), a 200 MB parameter file. So each reader
(Python sources, launch XML/YAML, parameter files, ``package.xml``,
``setup.py``/``setup.cfg``, ``CMakeLists.txt``, stubs) goes through
:func:`read_bytes`/:func:`read_text`, which

* resolves the path and refuses it when it leaves the workspace (a link
  inside the workspace to a file inside it is fine);
* opens it with ``O_NONBLOCK`` (a FIFO does not block the open) and
  ``O_NOFOLLOW`` on the resolved path (no link swapped in after resolving),
  then checks with ``fstat`` on the open descriptor that it is a regular file;
* reads at most the size limit plus one byte, so a file that grows or lies
  about its size still costs only the limit.

A refusal is an :class:`UnsafeFile` (an ``OSError``, so existing handlers turn
it into the file's own diagnostic); its message names the limit, never the
file's content.
"""
from __future__ import annotations

import functools
import os
import stat
from pathlib import Path

#: Largest Python source analysed (a bigger one is generated code, not a node).
MAX_SOURCE_BYTES = 4 * 1024 * 1024
#: Largest launch, parameter, manifest or build file read (real ones are a few KiB).
MAX_DATA_BYTES = 1024 * 1024

#: Folders no reader enters: VCS data, colcon build products, caches, virtual envs.
SKIP_DIRS = frozenset({
    ".git", ".hg", ".svn", "build", "install", "log", "__pycache__", ".tox", ".nox",
    ".venv", "venv", "node_modules", ".mypy_cache", ".pytest_cache", ".rosgraph-cache",
    "site-packages", ".eggs",
})

_NONBLOCK = getattr(os, "O_NONBLOCK", 0)
_FLAGS = os.O_RDONLY | _NONBLOCK | getattr(os, "O_NOFOLLOW", 0) \
    | getattr(os, "O_BINARY", 0) | getattr(os, "O_CLOEXEC", 0)


class UnsafeFile(OSError):
    """A file this tool will not read (outside the workspace, special, too large); the message says why."""


def _mib(limit: int) -> str:
    return f"{limit // (1024 * 1024)} MiB" if limit >= 1024 * 1024 else f"{limit} bytes"


def is_within(path: Path, folder: Path) -> bool:
    return path == folder or folder in path.parents


def resolve_inside(path: Path, root: Path | None) -> Path:
    """``path`` with links resolved; :class:`UnsafeFile` when that leaves ``root`` (``None``: anywhere)."""
    # On the resolved texts (absolute, normalised): every file read passes here, and
    # ``Path.parents`` builds a path object per folder above the file.
    resolved = _resolved(os.fspath(path))
    if root is not None:
        base = _resolved_folder(os.fspath(root))
        if resolved != base and not resolved.startswith(base if base.endswith(os.sep) else base + os.sep):
            raise UnsafeFile("not read: a link to a file outside the workspace")
    return Path(resolved)


def _resolved(text: str) -> str:
    """``os.path.realpath(text)``, the folders above a file that is no link resolved once per run
    (a workspace's files share a few hundred folders; resolving each path anew costs a system
    call per folder above it). Paths with ``..`` take the full resolution, whose order differs."""
    folder, name = os.path.split(text)
    if name in ("", os.curdir, os.pardir) or os.pardir in folder.split(os.sep):
        return os.path.realpath(text)
    try:
        if stat.S_ISLNK(os.lstat(text).st_mode):
            return os.path.realpath(text)
    except OSError:
        return os.path.realpath(text)
    return os.path.join(_real_folder(os.path.abspath(folder or os.curdir)), name)


@functools.lru_cache(maxsize=4096)
def _real_folder(folder: str) -> str:
    return os.path.realpath(folder)


@functools.lru_cache(maxsize=64)
def _resolved_folder(root: str) -> str:
    """The resolved folder a ``root`` stands for (its parent when it is a file)."""
    base = os.path.realpath(root)
    return base if os.path.isdir(base) else os.path.dirname(base)


def forget_folders() -> None:
    """Resolve folders anew from here on: a new run must see links as they are now."""
    _real_folder.cache_clear()
    _resolved_folder.cache_clear()


def _open_regular(path: Path, root: Path | None) -> tuple[int, os.stat_result]:
    """An open descriptor of the regular file ``path`` inside ``root``, set to blocking reads."""
    resolved = resolve_inside(Path(path), root)
    fd = os.open(resolved, _FLAGS)
    try:
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode):
            raise UnsafeFile("not read: not a regular file (a pipe, device or folder)")
        if _NONBLOCK:  # a regular file: plain blocking reads from here on
            os.set_blocking(fd, True)
    except BaseException:
        os.close(fd)
        raise
    return fd, info


def read_bytes(path: Path, root: Path | None, limit: int = MAX_DATA_BYTES) -> bytes:
    """The content of the regular file ``path`` inside ``root`` (see module docstring)."""
    fd, info = _open_regular(path, root)
    try:
        if info.st_size > limit:
            raise UnsafeFile(f"not read: larger than the {_mib(limit)} limit")
        chunks: list[bytes] = []
        size = 0
        while size <= limit:
            chunk = os.read(fd, min(1 << 16, limit + 1 - size))
            if not chunk:
                break
            chunks.append(chunk)
            size += len(chunk)
        if size > limit:  # it grew after fstat()
            raise UnsafeFile(f"not read: larger than the {_mib(limit)} limit")
        return b"".join(chunks)
    finally:
        os.close(fd)


def read_head(path: Path, root: Path | None, size: int) -> bytes:
    """The first ``size`` bytes (or fewer) of the regular file ``path`` inside ``root``, whatever its length."""
    fd, _ = _open_regular(path, root)
    try:
        return os.read(fd, size)
    finally:
        os.close(fd)


def read_text(path: Path, root: Path | None, limit: int = MAX_DATA_BYTES) -> str:
    """:func:`read_bytes` decoded as UTF-8 (``UnicodeDecodeError`` when it is not)."""
    return read_bytes(path, root, limit).decode("utf-8")


def describe(exc: Exception) -> str:
    """A short reason for a read failure, for a diagnostic (never the file's content)."""
    if isinstance(exc, UnicodeDecodeError):
        return "not UTF-8"
    if isinstance(exc, OSError) and exc.strerror:
        return exc.strerror
    return str(exc)


def is_regular_file(path: Path) -> bool:
    """Whether ``path`` is a regular file, without following a final link into a special file."""
    try:
        return stat.S_ISREG(os.stat(path).st_mode)
    except (OSError, ValueError):
        return False
