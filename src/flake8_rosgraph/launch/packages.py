"""ROS packages of a workspace and the executables they install, read statically.

A package is a folder with a ``package.xml``.  ``ros2 run pkg exe`` (and a
launch file's ``Node(package=…, executable=…)``) finds ``exe`` among

* ``console_scripts`` entry points of an ``ament_python`` package, in
  ``setup.cfg`` or in ``setup.py`` — the latter read with :mod:`ast` and a
  small constant folder (``package_name + '.talker:main'``, f-strings), never
  executed;
* ``add_executable(...)`` targets (and its wrappers, ``OUTPUT_NAME`` renames and
  components' ``EXECUTABLE``) and ``install(PROGRAMS ... DESTINATION
  lib/${PROJECT_NAME})`` scripts of an ``ament_cmake`` package.

When a package's list cannot be read completely (an entry point built at run
time, a CMake variable in a target name), :attr:`Package.complete` is false and
ROS201 stays quiet for it: an unknown list must not yield "no such executable".
"""
from __future__ import annotations

import ast
import configparser
import os
import xml.parsers.expat
from dataclasses import dataclass, field, replace
from pathlib import Path

from .. import inventory
from ..absint.folding import MAX_STR, safe_template, wide_template
from ..graph.model import Diagnostic
from ..cmake import cmake_commands, expand, literal_variables
from ..manifest import parse_manifest
from ..safe_io import describe, is_regular_file, is_within, read_bytes, read_text
from ..workspace import SKIP_DIRS, left_out
from .xml_front import XmlRefused


@dataclass(frozen=True)
class Executable:
    """One installed executable: a Python entry point (``module:function``) or a script/binary."""

    name: str
    module: str | None = None     # dotted module for console_scripts / root-relative path for scripts
    function: str | None = None
    script: str | None = None     # root-relative path of an installed Python script
    language: str = "python"      # "python" | "cpp"
    #: A compiled executable's source files (root-relative) and the component classes
    #: (``ns::Class``) it runs, as far as CMake names them literally.
    sources: tuple[str, ...] = ()
    plugins: tuple[str, ...] = ()
    #: The source files of the package's libraries it links (``target_link_libraries``).
    linked: tuple[str, ...] = ()


@dataclass
class Package:
    name: str
    path: str                     # root-relative folder ("." for a package at the root)
    build_type: str
    executables: dict[str, Executable] = field(default_factory=dict)
    complete: bool = True


@dataclass
class PackageIndex:
    packages: dict[str, Package] = field(default_factory=dict)
    diagnostics: list[Diagnostic] = field(default_factory=list)

    def folder(self, root: Path, name: str) -> Path | None:
        package = self.packages.get(name)
        return None if package is None else root / package.path


def _rel(path: Path, root: Path) -> str:
    rel = path.relative_to(root).as_posix()
    return rel or "."


def package_xml_files(root: Path, diagnostics: list[Diagnostic] | None = None) -> list[Path]:
    """Every ``package.xml`` under ``root``; a folder that cannot be listed is one of ``diagnostics``."""
    found: list[Path] = []

    def unreadable(error: OSError) -> None:
        if diagnostics is not None:
            where = Path(error.filename or root)
            rel = _rel(where, root) if is_within(where, root) else where.name
            diagnostics.append(Diagnostic(rel, 1, f"folder not read, packages in it are not known: "
                                                  f"{error.strerror or error}"))

    for dirpath, dirnames, filenames in inventory.walk(root, unreadable):
        why = left_out(Path(dirpath), filenames, root)
        if why is not None:
            dirnames[:] = []
            if diagnostics is not None:
                diagnostics.append(why)
            continue
        dirnames[:] = sorted(d for d in dirnames if d not in SKIP_DIRS and not d.startswith("."))
        if "package.xml" in filenames:
            found.append(Path(dirpath) / "package.xml")
    return sorted(found)


def _unread(path: Path, root: Path, exc: Exception, notes: list[Diagnostic]) -> None:
    """Note a package file that could not be read (the package's executables become unknown)."""
    notes.append(Diagnostic(_rel(path, root), 1,
                            f"not read, the package's executables are unknown: {describe(exc)}"))


def read_package(xml_path: Path, root: Path, notes: list[Diagnostic] | None = None) -> Package | Diagnostic:
    """The package of ``xml_path``; files it cannot read are added to ``notes``."""
    notes = [] if notes is None else notes
    rel = _rel(xml_path, root)
    try:
        manifest = parse_manifest(read_text(xml_path, root))
    except (OSError, UnicodeDecodeError) as exc:
        return Diagnostic(rel, 1, f"package.xml not read: {describe(exc)}")
    except (xml.parsers.expat.ExpatError, XmlRefused) as exc:
        return Diagnostic(rel, getattr(exc, "lineno", 1) or 1, f"package.xml not read: {exc}")
    if not manifest.name:
        return Diagnostic(rel, 1, "package.xml has no <name>")
    folder = xml_path.parent
    build_type = manifest.build_type or (
        "ament_python" if (folder / "setup.py").is_file() or (folder / "setup.cfg").is_file()
        else "ament_cmake")
    package = Package(manifest.name, _rel(folder, root), build_type)
    scripts = _console_scripts(folder, root, notes)
    if scripts is None:
        package.complete = False
    else:
        for exe in scripts:
            package.executables.setdefault(exe.name, exe)
    cmake = folder / "CMakeLists.txt"
    if cmake.exists():
        if not _cmake_executables(cmake, folder, root, package, notes):
            package.complete = False
    elif build_type != "ament_python":
        package.complete = False  # a compiled package whose build file we cannot see
    return package


# -- setup.cfg / setup.py -----------------------------------------------------------------------
def _entry(spec: str) -> Executable | None:
    name, sep, target = spec.partition("=")
    module, _, function = target.strip().partition(":")
    if not sep or not name.strip() or not module:
        return None
    return Executable(name.strip(), module.strip(), function.strip().split()[0] if function.strip() else None)


def _console_scripts(folder: Path, root: Path, notes: list[Diagnostic]) -> list[Executable] | None:
    """Entry points from setup.cfg and setup.py; ``None`` when setup.py hides them from static reading."""
    out: list[Executable] = []
    cfg = folder / "setup.cfg"
    if cfg.exists():
        parser = configparser.ConfigParser(interpolation=None)
        try:
            parser.read_string(read_text(cfg, root))
            raw = parser.get("options.entry_points", "console_scripts", fallback="")
        except (OSError, UnicodeDecodeError) as exc:
            _unread(cfg, root, exc, notes)
            return None
        except configparser.Error:
            return None
        out.extend(e for e in map(_entry, raw.splitlines()) if e is not None)
    setup = folder / "setup.py"
    if setup.exists():
        found = _setup_py_scripts(setup, root, notes)
        if found is None:
            return None
        out.extend(found)
    return out


class _Folder(ast.NodeVisitor):
    """Module-level constant assignments, so ``package_name + '.x:main'`` folds."""

    def __init__(self) -> None:
        self.names: dict[str, object] = {}

    def value(self, node: ast.expr) -> object:
        if isinstance(node, ast.Constant):
            return node.value
        if isinstance(node, ast.Name) and node.id in self.names:
            return self.names[node.id]
        if isinstance(node, (ast.List, ast.Tuple)):
            return [self.value(e) for e in node.elts]
        if isinstance(node, ast.Dict):
            return {self.value(k) if k is not None else None: self.value(v)
                    for k, v in zip(node.keys, node.values)}
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
            left, right = self.value(node.left), self.value(node.right)
            if isinstance(left, str) and isinstance(right, str) and len(left) + len(right) <= MAX_STR:
                return left + right
        if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Mod):
            left, right = self.value(node.left), self.value(node.right)
            if isinstance(left, str) and not wide_template(left):
                try:
                    return _bounded(left % (tuple(right) if isinstance(right, list) else right))
                except (TypeError, ValueError, KeyError):
                    return _UNKNOWN
        if isinstance(node, ast.JoinedStr):
            parts = []
            for part in node.values:
                if isinstance(part, ast.Constant):
                    parts.append(str(part.value))
                elif isinstance(part, ast.FormattedValue) and not part.format_spec:
                    inner = self.value(part.value)
                    if not isinstance(inner, (str, int)):
                        return _UNKNOWN
                    parts.append(str(inner))
                else:
                    return _UNKNOWN
            return _bounded("".join(parts))
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute) \
                and node.func.attr == "format" and not node.keywords:
            template = self.value(node.func.value)
            args = [self.value(a) for a in node.args]
            if isinstance(template, str) and safe_template(template) \
                    and all(isinstance(a, (str, int)) for a in args):
                try:
                    return _bounded(template.format(*args))
                except (IndexError, KeyError, ValueError):
                    return _UNKNOWN
        return _UNKNOWN


_UNKNOWN = object()


def _bounded(text: str) -> object:
    return text if len(text) <= MAX_STR else _UNKNOWN


def _setup_py_scripts(path: Path, root: Path, notes: list[Diagnostic]) -> list[Executable] | None:
    """The ``console_scripts`` of ``setup.py``; ``None`` when not statically readable (or too big/deep)."""
    try:
        tree = ast.parse(read_bytes(path, root), filename=str(path))
        return _setup_call_scripts(tree)
    except OSError as exc:
        _unread(path, root, exc, notes)
        return None
    except (RecursionError, MemoryError, OverflowError) as exc:
        _unread(path, root, ValueError(f"too deeply nested to read ({type(exc).__name__})"), notes)
        return None
    except (SyntaxError, ValueError):
        return None


def _setup_call_scripts(tree: ast.Module) -> list[Executable] | None:
    points = setup_entry_points(tree)
    if points is None:
        return None
    scripts = points.get("console_scripts", [])
    if not isinstance(scripts, list) or not all(isinstance(s, str) for s in scripts):
        return None
    return [e for e in map(_entry, scripts) if e is not None]


def setup_entry_points(tree: ast.Module) -> dict | None:
    """The ``entry_points`` of ``setup(...)`` in ``setup.py``, folded statically: ``{}`` when it
    has none, ``None`` when they cannot be read (``setup(**config)``, a computed value)."""
    folder = _Folder()
    for stmt in tree.body:
        if isinstance(stmt, ast.Assign) and len(stmt.targets) == 1 \
                and isinstance(stmt.targets[0], ast.Name):
            folder.names[stmt.targets[0].id] = folder.value(stmt.value)
    for call in ast.walk(tree):
        if not isinstance(call, ast.Call):
            continue
        func = call.func
        name = func.id if isinstance(func, ast.Name) else func.attr if isinstance(func, ast.Attribute) else ""
        if name != "setup":
            continue
        for keyword in call.keywords:
            if keyword.arg is None:
                return None  # setup(**config): the entry points are not visible
            if keyword.arg != "entry_points":
                continue
            points = folder.value(keyword.value)
            return points if isinstance(points, dict) else None
        return {}
    return {}


# -- CMakeLists.txt ---------------------------------------------------------------------------

#: How many CMakeLists.txt files ``add_subdirectory`` is followed through in one package.
MAX_CMAKE_FILES = 64
#: ``add_executable`` keywords that are no source file.
_EXECUTABLE_KEYWORDS = frozenset({"WIN32", "MACOSX_BUNDLE", "EXCLUDE_FROM_ALL", "IMPORTED", "ALIAS", "GLOBAL"})


def _cmake_executables(cmake: Path, folder: Path, root: Path, package: Package,
                       notes: list[Diagnostic], project: str | None = None,
                       seen: set[Path] | None = None) -> bool:
    """Add the CMake targets and installed scripts; false when a name is not literal.

    ``add_subdirectory(dir)`` is followed into ``dir/CMakeLists.txt`` (inside the workspace):
    its targets are the package's too, and it inherits ``PROJECT_NAME`` unless it has its own
    ``project()``; a subdirectory that cannot be read leaves the list incomplete.
    """
    seen = set() if seen is None else seen
    seen.add(cmake)
    try:
        commands = cmake_commands(read_text(cmake, root))
    except (OSError, UnicodeDecodeError) as exc:
        _unread(cmake, root, exc, notes)
        return False
    complete = True
    project = next((args[0] for name, args in commands if name == "project" and args), project)
    variables = literal_variables(commands)
    if project is not None:
        variables["PROJECT_NAME"] = project
    libraries: dict[str, tuple[str, ...]] = {}
    links: dict[str, list[str]] = {}
    for name, args in commands:
        args = [expand(arg, variables) for arg in args]
        if name == "add_subdirectory" and args:
            sub = Path(os.path.normpath(folder / args[0]))
            sub_cmake = sub / "CMakeLists.txt"
            if "$" in args[0] or len(seen) > MAX_CMAKE_FILES \
                    or not is_within(sub_cmake, root) or not is_regular_file(sub_cmake):
                complete = False
            elif sub_cmake not in seen:
                complete = _cmake_executables(sub_cmake, sub, root, package, notes, project, seen) and complete
            continue
        if name == "add_library" and args:
            libraries[args[0]] = _source_files(args[1:], folder, root)
        if name == "target_link_libraries" and len(args) > 1:
            links.setdefault(args[0], []).extend(args[1:])
        built = _built_executable(name, args)
        if built is not None:
            if "$" in built:
                complete = False
                continue
            sources: tuple[str, ...] = ()
            plugins: tuple[str, ...] = ()
            if name.endswith("add_executable") and args[1:2] != ["IMPORTED"]:
                sources = _source_files(args[1:], folder, root)
            elif name == "rclcpp_components_register_node":
                sources = libraries.get(args[0], ())
                if "PLUGIN" in args[:-1]:
                    plugins = (args[args.index("PLUGIN") + 1],)
            exe = package.executables.get(built)
            if exe is None or exe.language == "cpp":
                package.executables[built] = Executable(
                    built, language="cpp",
                    sources=tuple(sorted(set(exe.sources if exe else ()) | set(sources))),
                    plugins=tuple(sorted(set(exe.plugins if exe else ()) | set(plugins))))
        elif name == "install" and args and args[0].upper() == "PROGRAMS" and "DESTINATION" in args:
            at = args.index("DESTINATION")
            if args[at + 1:at + 2] not in (["lib/${PROJECT_NAME}"], [f"lib/{project}"]):
                continue
            items = args[1:at]
            # ``RENAME name`` installs the one file under another name (``tts_node.py`` as ``tts_node``).
            rename = args[args.index("RENAME") + 1] if "RENAME" in args[at:-1] and len(items) == 1 else None
            for item in items:
                if "$" in item or (rename is not None and "$" in rename):
                    complete = False
                    continue
                script = folder / item
                installed = rename or Path(item).name
                package.executables.setdefault(installed, Executable(
                    installed, script=_rel(script, root) if is_regular_file(script) else None))
    for target, linked in sorted(links.items()):
        exe = package.executables.get(target)
        found = sorted({source for library in linked for source in libraries.get(library, ())})
        if exe is not None and exe.language == "cpp" and found:
            package.executables[target] = replace(exe, linked=tuple(sorted(set(exe.linked) | set(found))))
    return complete


def _source_files(args: list[str], folder: Path, root: Path) -> tuple[str, ...]:
    """The literal C++ source files among a target's arguments (root-relative, existing)."""
    out = []
    for arg in args:
        if arg in _EXECUTABLE_KEYWORDS or "$" in arg or not arg.endswith((".cpp", ".cc", ".cxx", ".c++", ".C")):
            continue
        path = Path(os.path.normpath(folder / arg))
        if is_within(path, root) and is_regular_file(path):
            out.append(_rel(path, root))
    return tuple(out)


def _built_executable(command: str, args: list[str]) -> str | None:
    """The executable a CMake command builds, if it builds one.

    ``add_executable`` and its wrappers (``ament_auto_add_executable``,
    ``ament_add_gtest_executable``, ``cuda_add_executable`` …) name the target
    first; ``set_target_properties(… OUTPUT_NAME name)`` renames the file, and
    ``rclcpp_components_register_node(… EXECUTABLE name)`` builds a stand-alone
    executable for a component. Names are taken as possible executables even when
    no ``install(TARGETS …)`` is seen: a missed one must not yield "no such executable".
    """
    if not args:
        return None
    if command.endswith("add_executable") or (command.startswith("ament_add_") and command.endswith("_executable")):
        return args[0]
    keyword = {"set_target_properties": "OUTPUT_NAME", "rclcpp_components_register_node": "EXECUTABLE"}.get(command)
    if keyword is not None and keyword in args[:-1]:
        return args[args.index(keyword) + 1]
    return None


def find_packages(root: Path) -> PackageIndex:
    """Every package under ``root`` (a duplicate name: the first in path order wins, with a diagnostic).

    Each package is read on its own: one that cannot be read is a diagnostic on
    its ``package.xml``, never the loss of the others.
    """
    index = PackageIndex()
    root = Path(root)
    if not root.is_dir():
        return index
    for xml_path in package_xml_files(root, index.diagnostics):
        try:
            result = read_package(xml_path, root, index.diagnostics)
        except Exception as exc:  # one package's failure costs that package only
            result = Diagnostic(_rel(xml_path, root), 1,
                                f"package not read: internal error: {type(exc).__name__}: {exc}"[:300])
        if isinstance(result, Diagnostic):
            index.diagnostics.append(result)
        elif result.name in index.packages:
            index.diagnostics.append(Diagnostic(
                _rel(xml_path, root), 1,
                f"package '{result.name}' is also at {index.packages[result.name].path}; ignored"))
        else:
            index.packages[result.name] = result
    return index
