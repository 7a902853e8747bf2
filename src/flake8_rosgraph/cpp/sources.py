"""Finding and reading the C++ sources of a workspace's ROS packages, within limits.

Only files inside a ROS package (a folder with ``package.xml`` at or above
them) are read, not those of ``test``/``tests`` folders; folders the workspace leaves out
(ignore markers, ROS 1 packages: :func:`~flake8_rosgraph.workspace.left_out`),
colcon's ``build``/``install``/``log`` and hidden folders are skipped, symlinked
folders are not followed, and only regular files are opened. Only files that
mention ``rclcpp`` are parsed, and those that derive from a node class of such a
file (see :func:`flake8_rosgraph.cpp.to_graph.cpp_graph`): that keeps large C++
workspaces (vendored libraries, algorithms, tests) cheap.
"""
from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

from .. import inventory
from ..graph.model import Diagnostic
from ..safe_io import UnsafeFile, read_bytes
from ..workspace import SKIP_DIRS, left_out, relative
from . import CPP_SUFFIXES

#: Files larger than this are not read (generated code, not a node).
MAX_CPP_FILE_BYTES = 1024 * 1024
#: Folders of C++ tests (gtest): their nodes drive the package under test, and as partners they
#: would connect Python ends that nothing connects in a running system.
TEST_DIRS = frozenset({"test", "tests"})
#: What a file must contain to be parsed at all.
RCLCPP_MARKER = b"rclcpp"


@dataclass(frozen=True)
class CppSource:
    """One C++ file that mentions rclcpp: its root-relative path, its ROS package folder, its bytes."""

    path: str
    package: str
    data: bytes


def _package_files(root: Path) -> list[tuple[Path, str]]:
    """``(file, package folder)`` for every C++ file under a package folder, sorted by path."""
    found: list[tuple[Path, str]] = []
    packages: dict[str, str] = {}
    for dirpath, dirnames, filenames in inventory.walk(root):
        if left_out(Path(dirpath), filenames, root) is not None:
            dirnames[:] = []  # the Python walk reports the folder
            continue
        dirnames[:] = sorted(d for d in dirnames
                             if d not in SKIP_DIRS and d not in TEST_DIRS and not d.startswith("."))
        parent = packages.get(os.path.dirname(dirpath), "")
        package = relative(Path(dirpath), root) if "package.xml" in filenames else parent
        packages[dirpath] = package
        if "package.xml" in filenames or parent:
            found += [(Path(dirpath, name), package or ".") for name in sorted(filenames)
                      if os.path.splitext(name)[1] in CPP_SUFFIXES]
    return sorted(found, key=lambda item: item[0].as_posix())


def _read(path: Path, rel: str, root: Path) -> bytes | Diagnostic:
    """The file's bytes through the workspace's one safe opener (regular files inside ``root``, bounded)."""
    try:
        return read_bytes(path, root, MAX_CPP_FILE_BYTES)
    except UnsafeFile as exc:
        return Diagnostic(rel, 1, f"C++ file skipped: {str(exc).removeprefix('not read: ')}", "info")
    except OSError as exc:
        return Diagnostic(rel, 1, f"cannot read C++ file: {exc.strerror or exc}")


def cpp_sources(root: Path) -> tuple[list[CppSource], list[Diagnostic]]:
    """Every readable C++ file of ``root``'s packages, and why others could not be read."""
    root = Path(root)
    if not root.is_dir():
        return [], []
    sources: list[CppSource] = []
    diagnostics: list[Diagnostic] = []
    for path, package in _package_files(root):
        rel = relative(path, root)
        data = _read(path, rel, root)
        if isinstance(data, Diagnostic):
            diagnostics.append(data)
        else:
            sources.append(CppSource(rel, package, data))
    return sources, diagnostics


def mentions_rclcpp(source: CppSource) -> bool:
    return RCLCPP_MARKER in source.data


def included_names(source: CppSource) -> set[str]:
    """The file names (last path component) of the ``#include`` lines of a file."""
    names = set()
    for line in source.data.splitlines():
        line = line.strip()
        if line.startswith(b"#") and line[1:].lstrip().startswith(b"include"):
            target = line[1:].lstrip()[len(b"include"):].strip().strip(b'<>"')
            names.add(target.rsplit(b"/", 1)[-1].decode("utf-8", "replace"))
    return names
