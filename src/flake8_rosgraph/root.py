"""Which directory is "the workspace" of a checked file.

The graph rules judge whole-workspace facts, but flake8's file list says
nothing about the workspace: pre-commit passes only the changed files,
``ament_flake8`` passes none, ``flake8 .`` passes the root. So the workspace is
found from the checked file itself, in this order:

1. the nearest **colcon workspace** at or above the file: a directory ``WS``
   whose ``src/`` holds the file (or that is the checked directory itself) and
   either the file lies in a ROS package (a directory holding ``package.xml``)
   inside ``WS/src``, or ``WS/src`` holds ROS packages, or ``WS`` carries the
   ``COLCON_IGNORE`` markers colcon leaves in ``build/``, ``install/``, ``log/``. The whole workspace is the system that
   runs together, so it beats the repository it was cloned from;
2. the nearest **version-control root** (``.git``, ``.hg``, ``.svn``, ``.jj``),
   ignoring one in the home directory or at ``/`` (a dotfiles repository is not
   a ROS workspace);
3. otherwise the outermost of the folder the user named (when it holds the
   file: ``flake8 .``, ``check DIR``) and the file's ROS package directory,
   else the file's directory — never a folder the user did not name, and
   never ``/`` or the home directory, which hold far more than one project
   (walking them took minutes and gigabytes): a file directly in one of those
   is its own root, analysed alone.

A root found by that last fallback carries no mark of a ROS workspace. If no
``package.xml`` lies anywhere in it either and it holds more than
:data:`MAX_UNMARKED_PYTHON_FILES` Python files, it is refused
(:class:`RootRefused`): a folder like that is a home, a download or a library
tree, and analysing it took minutes and gigabytes to report nothing useful.

An explicit root (``--rosgraph-root`` / ``--root`` / ``ROSGRAPH_ROOT``) skips all of this.
"""
from __future__ import annotations

import os
from pathlib import Path

from .safe_io import SKIP_DIRS

#: Entries whose presence makes a directory a version-control root.
VCS_MARKERS: tuple[str, ...] = (".git", ".hg", ".svn", ".jj")
#: colcon writes COLCON_IGNORE into each of these when it builds a workspace.
COLCON_BASES: tuple[str, ...] = ("build", "install", "log")
#: The manifest that makes a directory a ROS package.
PACKAGE_MANIFEST = "package.xml"
#: A discovered root with no workspace marker and more Python files than this is refused.
MAX_UNMARKED_PYTHON_FILES = 2_000
#: Directory entries the size probe looks at before it calls an unmarked folder too large.
MAX_UNMARKED_ENTRIES = 100_000
#: How to name a root explicitly, in every front end's words.
OVERRIDE_HINT = "--rosgraph-root DIR (flake8), --root DIR (check) or ROSGRAPH_ROOT=DIR"


class RootRefused(Exception):
    """A discovered root that is clearly not a ROS workspace; the message says how to override."""


# The probes below run for every checked folder and each of its ancestors: they work on
# strings, as ``pathlib`` cost ten times the file system's answers.

def _start_dir(path: str | Path) -> str:
    path = os.path.abspath(path)
    return path if os.path.isdir(path) else os.path.dirname(path)


def _ancestors(path: str | Path) -> list[str]:
    folders = [_start_dir(path)]
    while (parent := os.path.dirname(folders[-1])) != folders[-1]:
        folders.append(parent)
    return folders


def _is_within(path: str, directory: str) -> bool:
    return path == directory or path.startswith(directory.rstrip(os.sep) + os.sep)


def _has_colcon_markers(directory: str) -> bool:
    return any(os.path.isfile(os.path.join(directory, base, "COLCON_IGNORE")) for base in COLCON_BASES)


def _holds_packages(src: str) -> bool:
    """Whether ``src`` holds a ROS package within three levels (``src/repo/group/pkg``)."""
    patterns = ("*/" + PACKAGE_MANIFEST, "*/*/" + PACKAGE_MANIFEST, "*/*/*/" + PACKAGE_MANIFEST)
    return any(next(Path(src).glob(pattern), None) is not None for pattern in patterns)


def find_colcon_root(path: str | Path) -> Path | None:
    """The nearest colcon workspace that is ``path`` or holds it in its ``src/`` tree, if any."""
    start = _start_dir(path)
    inside_package = False
    for directory in _ancestors(start):
        src = os.path.join(directory, "src")
        if (start == directory or _is_within(start, src)) and os.path.isdir(src):
            if inside_package or _has_colcon_markers(directory) or _holds_packages(src):
                return Path(directory)
        if os.path.isfile(os.path.join(directory, PACKAGE_MANIFEST)):
            inside_package = True
    return None


def find_vcs_root(path: str | Path) -> Path | None:
    """The nearest version-control root above ``path`` (not the home directory or ``/``)."""
    folders = _ancestors(path)
    excluded = {folders[-1]}  # the file system's root
    try:
        excluded.add(os.path.abspath(Path.home()))
    except RuntimeError:  # no home directory to protect
        pass
    for directory in folders:
        if directory not in excluded and any(os.path.exists(os.path.join(directory, marker))
                                             for marker in VCS_MARKERS):
            return Path(directory)
    return None


def find_package_dir(path: str | Path) -> Path | None:
    """The nearest ROS package directory (one holding ``package.xml``) above ``path``."""
    for directory in _ancestors(path):
        if os.path.isfile(os.path.join(directory, PACKAGE_MANIFEST)):
            return Path(directory)
    return None


def _protected() -> set[Path]:
    """Folders never taken as a fallback root: filesystem roots and the home directory."""
    protected = {Path(os.path.abspath(os.sep))}
    try:
        protected.add(Path(os.path.abspath(Path.home())))
    except RuntimeError:  # no home directory to protect
        pass
    return protected


def discover_root(path: Path, given: Path | None = None) -> Path:
    """The workspace root for ``path`` (a file or directory), found as the module docstring says.

    ``given`` is the folder the user named that holds ``path`` (``flake8 DIR``);
    a directory ``path`` is a named folder itself.
    """
    start = Path(_start_dir(path))
    found = find_colcon_root(start) or find_vcs_root(start)
    if found is not None:
        return found
    protected = _protected() | {Path(start.anchor)}
    candidates = [start]
    if given is not None:
        named = Path(os.path.abspath(given))
        if _is_within(str(start), str(named)) and named not in protected:
            candidates.append(named)
    package = find_package_dir(start)
    if package is not None and package not in protected:
        candidates.append(package)
    chosen = min(candidates, key=lambda p: len(p.parts))
    absolute = Path(os.path.abspath(path))
    if chosen in protected and absolute != start:
        return absolute  # a lone file in / or $HOME: analysed alone, nothing walked
    if package is None:
        _refuse_if_large(chosen)
    return chosen


def _refuse_if_large(folder: Path) -> None:
    """Raise :class:`RootRefused` when ``folder`` holds no ``package.xml`` and is large.

    The probe walks as the workspace walk does (no symlinks, build and hidden
    folders skipped) and stops at the first ``package.xml`` or at the limits, so
    it costs little either way.
    """
    python_files = entries = 0
    for dirpath, dirnames, filenames in os.walk(folder, followlinks=False):
        if PACKAGE_MANIFEST in filenames:
            return
        dirnames[:] = sorted(d for d in dirnames if d not in SKIP_DIRS and not d.startswith("."))
        entries += len(dirnames) + len(filenames)
        python_files += sum(name.endswith(".py") for name in filenames)
        if python_files > MAX_UNMARKED_PYTHON_FILES:
            size = f"{MAX_UNMARKED_PYTHON_FILES:,} Python files"
        elif entries > MAX_UNMARKED_ENTRIES:
            size = f"{MAX_UNMARKED_ENTRIES:,} files and folders"
        else:
            continue
        raise RootRefused(
            f"{folder}: not analysed: nothing marks it as a ROS workspace (no package.xml, "
            f"version-control root or colcon layout) and it holds more than {size}; run from "
            f"inside your workspace, or name the root with {OVERRIDE_HINT} to analyse it anyway")
