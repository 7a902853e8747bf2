"""Finding and reading the Python files of a workspace, robustly.

Walks the tree (no symlink following, so loops cannot trap it), skips build
products and hidden/virtual-env folders, names each file as the module Python
would import it as (walking up through ``__init__.py`` packages), and parses it.
A file that cannot be read, decoded or parsed becomes a :class:`Diagnostic` and
is left out; everything else is still analysed.
"""
from __future__ import annotations

import ast
import functools
import hashlib
import io
import os
import re
import sys
import tokenize
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Mapping

from .absint.outline import attribute_stores, declared_names, edits_sys_path, import_statements
from .absint.program import Module
from .graph.model import Diagnostic
from .options import Buffers
from . import inventory
from .cmake import cmake_commands
from .manifest import parse_manifest
from .safe_io import MAX_SOURCE_BYTES, SKIP_DIRS, UnsafeFile, read_bytes, read_head

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


#: Files whose presence makes a folder a distribution root (a ROS package or a Python
#: project): the folder holds Python packages, it is never one itself.
DIST_MARKERS = ("package.xml", "setup.py", "setup.cfg", "pyproject.toml")
#: Bytes read from an extension-less file to look for a Python shebang.
SHEBANG_BYTES = 256
_SHEBANG = re.compile(rb"^#![^\n]*\bpython[0-9.]*\b")
#: Scripts named by a build file: ``scripts=[…]`` in setup.py, ``scripts =`` in setup.cfg
#: (``install(PROGRAMS …)`` in CMakeLists.txt is read with the linear :mod:`.cmake` scanner).
_SETUP_SCRIPTS = re.compile(r"\bscripts\s*=\s*\[([^\]]*)\]")
_CFG_SCRIPTS = re.compile(r"^scripts\s*=\s*((?:.*\n(?:[ \t]+.*\n?)*))", re.MULTILINE)
_PACKAGE_DIR = re.compile(r"package_dir\s*=\s*\{\s*['\"]{2}\s*:\s*['\"]([\w./-]+)['\"]")
_CFG_PACKAGE_DIR = re.compile(r"^package_dir\s*=\s*\n?\s*=\s*([\w./-]+)", re.MULTILINE)
#: Build files read for script names and package_dir are small; bigger ones are skipped.
MAX_BUILD_FILE_BYTES = 256 * 1024


#: Marker files that tell the ROS build tools (colcon, ament, catkin) to leave a folder out.
IGNORE_MARKERS = ("COLCON_IGNORE", "AMENT_IGNORE", "CATKIN_IGNORE")
#: A package.xml larger than this is not read to tell ROS 1 from ROS 2 (the package stays in).
MAX_MANIFEST_BYTES = 256 * 1024


def left_out(folder: Path, filenames: list[str], root: Path) -> Diagnostic | None:
    """Why the subtree at ``folder`` is not part of the ROS 2 workspace (``None``: it is).

    A folder with an ignore marker is not built; a catkin package is ROS 1 code — rospy
    nodes, genpy messages that take ints for floats and positional arguments, roslaunch
    XML — which the ROS 2 rules would misjudge. Every walker prunes the same subtrees,
    so the Python modules, launch files and packages of the workspace agree.
    """
    marker = next((m for m in IGNORE_MARKERS if m in filenames), None)
    if marker is not None:
        return Diagnostic(relative(folder / marker, root), 1,
                          f"{marker}: the build leaves this folder out; not analysed", "info")
    if "package.xml" not in filenames:
        return None
    return inventory.remember(("ros1", str(folder), str(root)), lambda: _ros1_left_out(folder, root))


def _ros1_left_out(folder: Path, root: Path) -> Diagnostic | None:
    """The ROS 1 part of :func:`left_out`, asked once a run (every walker asks it of every package)."""
    text = _small_text(folder / "package.xml", MAX_MANIFEST_BYTES)
    ros1 = _ros1_package(text) if text is not None else None
    if ros1 is not None:
        return Diagnostic(relative(folder / "package.xml", root), 1,
                          f"ROS 1 (catkin) package '{ros1}': not analysed "
                          "(the rules check ROS 2 code)", "info")
    return None


@functools.lru_cache(maxsize=1024)
def _ros1_package(text: str) -> str | None:
    """The name of the ROS 1 (catkin) package whose manifest is ``text``; ``None`` for any other
    manifest or one that cannot be read. Kept by text: every walker of the workspace asks
    about the same package.xml files."""
    try:
        manifest = parse_manifest(text)
    except Exception:  # an unreadable manifest is reported by the package reader
        return None
    return manifest.name if manifest.is_ros1 else None


def python_files(root: Path, skipped: list[Diagnostic] | None = None) -> list[Path]:
    """The Python files under ``root`` (or ``root`` itself), sorted, build folders skipped:
    every ``*.py``, and executables without the suffix — files with a Python shebang and
    files a build file installs as scripts (setup.py/setup.cfg ``scripts``, CMake
    ``install(PROGRAMS …)``) — which ROS packages ship as nodes. Subtrees the workspace
    leaves out (:func:`left_out`) are pruned, each one of ``skipped``."""
    if root.is_file():
        return [root]
    found: list[Path] = []
    listed: set[Path] = set()  # build files sit above their scripts: walked first (top-down)
    for dirpath, dirnames, filenames in inventory.walk(root):
        folder = Path(dirpath)
        why = left_out(folder, filenames, root)
        if why is not None:
            dirnames[:] = []
            if skipped is not None:
                skipped.append(why)
            continue
        dirnames[:] = sorted(d for d in dirnames
                             if d not in SKIP_DIRS and not d.startswith(".")
                             and not d.endswith(".egg-info"))
        listed |= _listed_scripts(folder, filenames)
        for name in sorted(filenames):
            path = folder / name
            if name.endswith(".py") or (
                    "." not in name and (path in listed or _has_python_shebang(path))):
                found.append(path)
    return sorted(found)


def _small_text(path: Path, limit: int) -> str | None:
    """The text of a regular file of at most ``limit`` bytes, else ``None`` (the safe opener's rules)."""
    try:
        return read_bytes(path, None, limit).decode("utf-8", "replace")
    except OSError:
        return None


def _has_python_shebang(path: Path) -> bool:
    try:
        return bool(_SHEBANG.match(read_head(path, None, SHEBANG_BYTES)))
    except OSError:
        return False


def _listed_scripts(folder: Path, filenames: list[str]) -> set[Path]:
    """Files the build files in ``folder`` install as executables."""
    names = set(filenames)
    words: list[str] = []
    for build, pattern in (("setup.py", _SETUP_SCRIPTS), ("setup.cfg", _CFG_SCRIPTS)):
        if build in names:
            for match in pattern.finditer(_small_text(folder / build, MAX_BUILD_FILE_BYTES) or ""):
                words += re.split(r"[\s,]+", match.group(1))
    if "CMakeLists.txt" in names:
        for command, args in cmake_commands(_small_text(folder / "CMakeLists.txt", MAX_BUILD_FILE_BYTES) or ""):
            if command == "install" and args and args[0].upper() == "PROGRAMS":
                words += args[1:args.index("DESTINATION")] if "DESTINATION" in args else args[1:]
    return {folder / word for word in (w.strip("'\"") for w in words)
            if word and not word.startswith("$") and ".." not in word}


def source_roots(folder: Path) -> set[Path]:
    """Folders under a distribution root ``folder`` that hold top-level Python packages:
    the folder itself, ``src``, and a ``package_dir={'': …}`` of setup.py/setup.cfg."""
    out = {folder, folder / "src"}
    for build, pattern in (("setup.py", _PACKAGE_DIR), ("setup.cfg", _CFG_PACKAGE_DIR)):
        text = _small_text(folder / build, MAX_BUILD_FILE_BYTES)
        for match in pattern.finditer(text or ""):
            out.add(folder / match.group(1).strip("/"))
    return out


def _is_source_root(folder: Path) -> bool:
    """Whether ``folder`` holds top-level packages (so it is not a package itself, even
    with a stray ``__init__.py``): a distribution root, or a source root of the one above."""
    if any((folder / marker).is_file() for marker in DIST_MARKERS):
        return True
    parent = folder.parent
    return any((parent / marker).is_file() for marker in DIST_MARKERS) \
        and folder in source_roots(parent)


def _inside_package(folder: Path, memo: dict[Path, bool] | None) -> bool:
    """Whether ``folder`` is a package folder the import name goes up through (kept in ``memo``
    per folder when given: the files of a package ask about the same folders above them)."""
    known = memo.get(folder) if memo is not None else None
    if known is None:
        known = (folder / "__init__.py").is_file() and folder != folder.parent \
            and not _is_source_root(folder)
        if memo is not None:
            memo[folder] = known
    return known


def module_name(path: Path, root: Path, memo: dict[Path, bool] | None = None) -> tuple[str, bool]:
    """Dotted import name of ``path`` (packages found by ``__init__.py``), and whether it is a
    package.

    The walk up through ``__init__.py`` folders stops at a distribution root (a folder with
    package.xml, setup.py, setup.cfg or pyproject.toml) and at its ``src``/``package_dir``
    folder: Python computes import names from there, so a stray ``__init__.py`` in a ROS
    package's root or in ``src/`` does not become part of every module's name.
    """
    is_package = path.name == "__init__.py"
    parts = [] if is_package else [path.stem]
    folder = path.parent
    while _inside_package(folder, memo):
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


def read_module(path: Path, root: Path, buffer: bytes | None = None,
                package_memo: dict[Path, bool] | None = None) -> Module | Diagnostic:
    """The module of ``path`` (``buffer``: the editor's unsaved content, parsed instead of the file;
    ``package_memo``: see :func:`module_name`)."""
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
    name, is_package = module_name(path, root if root.is_dir() else root.parent, package_memo)
    wide = {} if text.isascii() else {  # numbered as Python's tokenizer numbers lines
        number: line for number, line in enumerate(_LINE_BREAKS.split(text), 1) if not line.isascii()}
    first = text.split("\n", 1)[0]
    program = first.startswith("#!") and "python" in first
    return Module(name, rel, tree, wide, is_package, program, digest=hashlib.sha256(data).hexdigest(),
                  imports=import_statements(tree), declares=declared_names(tree),
                  attribute_stores=attribute_stores(tree, b"setattr" in data),
                  edits_sys_path=edits_sys_path(tree, b"sys.path" in data), lines=text.count("\n") + 1)


@dataclass
class Outlines:
    """What earlier runs learnt of each Python file that parsed, by content digest: whether it
    is a program, its import statements, the names it declares, the attribute names it
    assigns, whether it edits ``sys.path`` and its number of lines (``["ok", program, statements,
    declares, stores, edits_path, lines]``, as JSON; see :mod:`.absint.outline`).

    With the digests the cache key computed (:class:`.cache.InputDigests`, by file identity), a
    file whose outline is known is made into a module without being read or parsed: only the
    groups of modules that must be analysed again read theirs (:attr:`.Module.source`).
    """

    known: dict[str, Any]
    #: This run's digest of each root-relative path (the cache key's).
    digests: Mapping[str, str]
    #: The outlines of this run's files: what the cache keeps for the next run.
    used: dict[str, Any] = field(default_factory=dict)

    def module(self, path: Path, root: Path, package_memo: dict[Path, bool]) -> Module | None:
        """The module of ``path`` made from its outline, ``None`` when there is none to trust."""
        rel = relative(path, root)
        digest = self.digests.get(rel)
        outline = self.known.get(digest) if digest is not None else None
        statements = _statements(outline)
        if statements is None or not _names(outline[3], allow_none=True) or not _names(outline[4]):
            return None
        self.used[digest] = outline
        name, is_package = module_name(path, root if root.is_dir() else root.parent, package_memo)
        return Module(name, rel, None, {}, is_package, outline[1], digest=digest, imports=statements,
                      declares=None if outline[3] is None else tuple(outline[3]),
                      attribute_stores=frozenset(outline[4]), edits_sys_path=outline[5], lines=outline[6],
                      source=functools.partial(_parse_again, path, root))

    def learn(self, module: Module) -> None:
        self.used[module.digest] = ["ok", module.program, [list(s) for s in module.imports],
                                    None if module.declares is None else list(module.declares),
                                    sorted(module.attribute_stores), module.edits_sys_path, module.lines]


def _names(item: Any, allow_none: bool = False) -> bool:
    """Whether an outline's entry is a list of names (or ``None`` where that is allowed)."""
    if item is None:
        return allow_none
    return isinstance(item, list) and all(isinstance(name, str) for name in item)


def _statements(outline: Any) -> tuple | None:
    """The import statements of a well-formed outline, else ``None``."""
    if not (isinstance(outline, list) and len(outline) == 7 and outline[0] == "ok"
            and isinstance(outline[1], bool) and isinstance(outline[2], list) and isinstance(outline[5], bool)
            and type(outline[6]) is int):
        return None
    out = []
    for item in outline[2]:
        if isinstance(item, list) and len(item) == 2 and item[0] == "import" and isinstance(item[1], str):
            out.append(("import", item[1]))
        elif isinstance(item, list) and len(item) == 4 and item[0] == "from" \
                and (item[1] is None or isinstance(item[1], str)) and isinstance(item[2], int) \
                and isinstance(item[3], list) and all(isinstance(n, str) for n in item[3]):
            out.append(("from", item[1], item[2], tuple(item[3])))
        else:
            return None
    return tuple(out)


def _parse_again(path: Path, root: Path) -> tuple[ast.Module, dict[int, str]]:
    """The tree of a module made from its outline, when its group is analysed after all (a file
    that no longer reads or parses — changed since the key was taken — is an empty module)."""
    found = read_module(path, root)
    if isinstance(found, Diagnostic):
        return ast.Module(body=[], type_ignores=[]), {}
    return found.tree, found.wide_lines


def load_workspace(root: Path, buffers: Buffers = (), outlines: Outlines | None = None,
                   files: list[Path] | None = None) -> Workspace:
    """Read every Python file under ``root``; unique module names (duplicates get a path-based one).

    ``buffers`` replace the content of the files they name (an editor's unsaved buffer);
    with ``outlines``, a file whose outline is known is read only if its tree is needed;
    ``files``: the Python files when already found (what :func:`python_files` would walk for,
    the folders it leaves out reported by whoever found them).
    """
    modules: list[Module] = []
    diagnostics: list[Diagnostic] = []
    names: set[str] = set()
    unsaved = dict(buffers)
    package_memo: dict[Path, bool] = {}
    for path in python_files(root, diagnostics) if files is None else files:
        buffer = unsaved.get(os.path.abspath(path))
        result = outlines.module(path, root, package_memo) if outlines is not None and buffer is None \
            else None
        if result is None:
            result = read_module(path, root, buffer, package_memo)
            if outlines is not None and buffer is None and isinstance(result, Module):
                outlines.learn(result)
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
