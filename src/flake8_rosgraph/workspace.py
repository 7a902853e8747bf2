"""Finding and reading the Python files of a workspace, robustly.

Walks the tree (no symlink following, so loops cannot trap it), skips build
products and hidden/virtual-env folders, names each file as the module Python
would import it as (walking up through ``__init__.py`` packages), and parses it.
A file that cannot be read, decoded or parsed becomes a :class:`Diagnostic` and
is left out; everything else is still analysed.
"""
from __future__ import annotations

import ast
import io
import os
import re
import sys
import tokenize
from dataclasses import dataclass
from pathlib import Path

from .absint.program import Module
from .graph.model import Diagnostic
from .options import Buffers
from .safe_io import MAX_SOURCE_BYTES, SKIP_DIRS, UnsafeFile, read_bytes

#: On Python 3.10, a line with more call/attribute/subscript links than this is not parsed
#: (its parser may segfault on such chains instead of raising).
MAX_CHAIN_PY310 = 20_000
#: Files larger than this are not analysed (a generated file, not a node).
MAX_FILE_BYTES = MAX_SOURCE_BYTES


@dataclass
class Workspace:
    root: Path
    modules: list[Module]
    diagnostics: list[Diagnostic]


def python_files(root: Path) -> list[Path]:
    """All ``*.py`` files under ``root`` (or ``root`` itself), sorted, build folders skipped."""
    if root.is_file():
        return [root]
    found: list[Path] = []
    for dirpath, dirnames, filenames in os.walk(root, followlinks=False, onerror=None):
        dirnames[:] = sorted(d for d in dirnames
                             if d not in SKIP_DIRS and not d.startswith(".")
                             and not d.endswith(".egg-info"))
        for name in sorted(filenames):
            if name.endswith(".py"):
                found.append(Path(dirpath) / name)
    return sorted(found)


def module_name(path: Path, root: Path) -> tuple[str, bool]:
    """Dotted import name of ``path`` (packages found by ``__init__.py``), and whether it is a package."""
    is_package = path.name == "__init__.py"
    parts = [] if is_package else [path.stem]
    folder = path.parent
    while (folder / "__init__.py").is_file() and folder != folder.parent:
        parts.insert(0, folder.name)
        if folder == root:
            break
        folder = folder.parent
    return ".".join(parts) or path.stem, is_package


def relative(path: Path, root: Path) -> str:
    base = root if root.is_dir() else root.parent
    try:
        return path.relative_to(base).as_posix()
    except ValueError:
        return path.name


_LINE_BREAKS = re.compile(r"\r\n|\r|\n")


def _chain_links(line: str) -> int:
    return line.count("(") + line.count(".") + line.count("[")


def read_module(path: Path, root: Path, buffer: bytes | None = None) -> Module | Diagnostic:
    """The module of ``path`` (``buffer``: the editor's unsaved content, parsed instead of the file)."""
    rel = relative(path, root)
    try:
        data = buffer if buffer is not None and len(buffer) <= MAX_FILE_BYTES else read_bytes(path, root, MAX_FILE_BYTES)
    except UnsafeFile as exc:
        return Diagnostic(rel, 1, f"skipped: {exc}".replace("skipped: not read: ", "skipped: "))
    except OSError as exc:
        return Diagnostic(rel, 1, f"cannot read file: {exc.strerror or exc}")
    try:
        encoding, _ = tokenize.detect_encoding(io.BytesIO(data).readline)
        text = data.decode(encoding)
    except (SyntaxError, LookupError, UnicodeDecodeError) as exc:
        return Diagnostic(rel, 1, f"cannot decode file: {exc}")
    if sys.version_info < (3, 11):
        for number, line in enumerate(text.splitlines(), 1):
            if len(line) > MAX_CHAIN_PY310 and _chain_links(line) > MAX_CHAIN_PY310:
                # CPython 3.10's parser can crash the interpreter (not raise) on such chains.
                return Diagnostic(rel, number, "skipped: an expression nested too deeply to "
                                               "parse safely on Python 3.10")
    try:
        tree = ast.parse(data, filename=rel)
    except SyntaxError as exc:
        return Diagnostic(rel, exc.lineno or 1, f"syntax error: {exc.msg}")
    except (ValueError, RecursionError, MemoryError, OverflowError) as exc:
        return Diagnostic(rel, 1, f"cannot parse file: {type(exc).__name__}: {exc}"[:200])
    name, is_package = module_name(path, root if root.is_dir() else root.parent)
    wide = {} if text.isascii() else {  # numbered as Python's tokenizer numbers lines
        number: line for number, line in enumerate(_LINE_BREAKS.split(text), 1) if not line.isascii()}
    return Module(name, rel, tree, wide, is_package)


def load_workspace(root: Path, buffers: Buffers = ()) -> Workspace:
    """Read every Python file under ``root``; unique module names (duplicates get a path-based one).

    ``buffers`` replace the content of the files they name (an editor's unsaved buffer).
    """
    modules: list[Module] = []
    diagnostics: list[Diagnostic] = []
    names: set[str] = set()
    unsaved = dict(buffers)
    for path in python_files(root):
        result = read_module(path, root, unsaved.get(os.path.abspath(path)))
        if isinstance(result, Diagnostic):
            diagnostics.append(result)
            continue
        if result.name in names:
            # Two files claim one import name (e.g. same-named scripts in two packages):
            # keep both analysed; imports resolve to the first.
            result.name = "<file>" + result.path
        names.add(result.name)
        modules.append(result)
    return Workspace(root, modules, diagnostics)
