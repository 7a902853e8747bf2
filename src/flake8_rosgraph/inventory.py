"""The workspace's folders, listed once per run and shared by every reader.

A run walks the workspace several times, each reader for its own files: the cache key
(every input), the Python modules, the packages, the launch files, the interface files,
the classes frameworks register, the C++ sources. Each walk listed the same folders again,
and each reader asked of every ``package.xml`` whether it is a ROS 1 package.

Inside :func:`shared`, :func:`walk` lists each folder once (with :func:`os.scandir`, as
:func:`os.walk` does) and hands every later walker the same listing, so all readers of one
run also see one and the same tree — a file created while the run walks is in all of their
views or in none. Outside it, :func:`walk` is :func:`os.walk`. Each walker still prunes the
folders it does not enter by editing ``dirnames`` in place, as with :func:`os.walk`; links
to folders are listed and never entered. :meth:`Inventory.remember` keeps the answers to
questions about a folder (:func:`~flake8_rosgraph.workspace.left_out`) for the run.
"""
from __future__ import annotations

import contextlib
import os
from collections.abc import Callable, Iterator
from contextvars import ContextVar
from dataclasses import dataclass
from typing import TypeVar

T = TypeVar("T")


@dataclass(frozen=True)
class _Listing:
    """One folder as :func:`os.walk` sees it: subfolders (links among them, never entered) and
    other entries, in the order the file system gives them; or why it could not be listed."""

    dirnames: tuple[str, ...] = ()
    links: frozenset[str] = frozenset()
    filenames: tuple[str, ...] = ()
    error: OSError | None = None


class Inventory:
    """The folders listed so far in one run, and what was remembered about them."""

    def __init__(self, root: str) -> None:
        self.root = root
        self._listings: dict[str, _Listing] = {}
        self._remembered: dict[tuple, object] = {}

    def covers(self, top: str) -> bool:
        return top == self.root or top.startswith(self.root.rstrip(os.sep) + os.sep)

    def walk(self, top: str, onerror: Callable[[OSError], None] | None) -> Iterator[tuple[str, list[str], list[str]]]:
        """:func:`os.walk` ``(top, followlinks=False)`` from the listings: top-down, each folder
        after its parent, in the order the caller leaves in ``dirnames``, named from ``top`` as
        given (folders are listed once whichever way a walker names them)."""
        stack = [(top, os.path.abspath(top))]
        while stack:
            folder, absolute = stack.pop()
            listing = self._listing(absolute)
            if listing.error is not None:
                if onerror is not None:
                    onerror(listing.error)
                continue
            dirnames, filenames = list(listing.dirnames), list(listing.filenames)
            yield folder, dirnames, filenames
            stack += [(os.path.join(folder, name), os.path.join(absolute, name))
                      for name in reversed(dirnames) if name not in listing.links]

    def remember(self, key: tuple, compute: Callable[[], T]) -> T:
        """``compute()``, once per ``key`` in this run."""
        try:
            return self._remembered[key]  # type: ignore[return-value]
        except KeyError:
            found = self._remembered[key] = compute()
            return found

    def _listing(self, folder: str) -> _Listing:
        listing = self._listings.get(folder)
        if listing is None:
            listing = self._listings[folder] = _list(folder)
        return listing


def _list(folder: str) -> _Listing:
    """What :func:`os.walk` lists of ``folder``: an entry is a folder if it is one, through a
    link or not (a link is listed as a folder, not entered); an entry that cannot be inspected
    is not a folder."""
    dirnames: list[str] = []
    links: set[str] = set()
    filenames: list[str] = []
    try:
        with os.scandir(folder) as entries:
            for entry in entries:
                try:
                    is_dir = entry.is_dir()
                except OSError:
                    is_dir = False
                if not is_dir:
                    filenames.append(entry.name)
                    continue
                dirnames.append(entry.name)
                try:
                    if entry.is_symlink():
                        links.add(entry.name)
                except OSError:
                    links.add(entry.name)  # cannot tell: not entered, as os.walk does
    except OSError as exc:
        return _Listing(error=exc)
    return _Listing(tuple(dirnames), frozenset(links), tuple(filenames))


_CURRENT: ContextVar[Inventory | None] = ContextVar("flake8_rosgraph_inventory", default=None)


@contextlib.contextmanager
def shared(root: str | os.PathLike[str], taken: Inventory | None = None) -> Iterator[Inventory]:
    """Share one inventory of ``root`` among the walks inside the ``with`` block: the one already
    shared when it covers ``root``, else ``taken`` (a listing this run took earlier of the same
    root), else a new one."""
    current = _CURRENT.get()
    top = os.path.abspath(root)
    if current is not None and current.covers(top):
        yield current
        return
    inventory = taken if taken is not None and taken.root == top else Inventory(top)
    token = _CURRENT.set(inventory)
    try:
        yield inventory
    finally:
        _CURRENT.reset(token)


def walk(top: str | os.PathLike[str], onerror: Callable[[OSError], None] | None = None
         ) -> Iterator[tuple[str, list[str], list[str]]]:
    """:func:`os.walk` ``(top, followlinks=False, onerror=onerror)``, from the shared inventory
    when one covers ``top``."""
    current = _CURRENT.get()
    path = os.fspath(top)
    if current is None or not current.covers(os.path.abspath(path)):
        return os.walk(path, followlinks=False, onerror=onerror)
    return current.walk(path, onerror)


def remember(key: tuple, compute: Callable[[], T]) -> T:
    """``compute()``, once per ``key`` while an inventory is shared (every time otherwise)."""
    current = _CURRENT.get()
    return compute() if current is None else current.remember(key, compute)
