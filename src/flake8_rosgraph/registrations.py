"""Classes that frameworks instantiate, read from the packages' metadata, never from running them.

Much rclpy code lives in classes no code of the workspace constructs: a ``ros2``
command-line verb (``ros2cli.command``, ``ros2topic.verb`` … entry points), an rqt
plugin (exported through ``plugin.xml``), a launch or test extension. The framework
finds them by name in the package's metadata and builds them itself, so they are
entry points of the analysis like ``console_scripts`` are:

* every entry point group but ``console_scripts``/``gui_scripts`` of ``setup.py``
  (read statically), ``setup.cfg`` and ``pyproject.toml`` (``[project.entry-points.*]``):
  ``name = package.module:Class``;
* every ``<class type="package.module.Class">`` of the plugin description files a
  ``package.xml`` exports (``<rqt_gui plugin="${prefix}/plugin.xml"/>``); C++ classes
  (``ns::Class``) are not Python and are left out;
* every ``<plugin type="package.module.Class">`` inside ``<webots>`` of the package's robot
  descriptions (``*.urdf``, ``*.xacro``): webots_ros2_driver imports and builds the class and
  calls its ``init(webots_node, properties)`` and ``step()`` (C++ plugins, ``ns::Class``, are
  left out);
* every class a C++ file of the package builds through pybind11's embedded interpreter
  (``auto m = py::module::import("pkg.module"); m.attr("Class")(...)``): a hybrid node whose
  Python half no Python code constructs.

The result is a set of dotted ``module.Class`` names; a name that is no class of the
workspace (a function, a missing module) is simply never matched. A ``plugin.xml`` class also
says which framework loads it (``base_class_type="rqt_gui_py::Plugin"``), which its Python
base need not: rqt plugins commonly derive from ``qt_gui.plugin.Plugin`` and are still built
by rqt_gui_py's provider, with its ROS 2 context. The result maps each name to that type, for
the library model to match (``registered_as``).
"""
from __future__ import annotations

import ast
import configparser
import os
import re
import sys
import xml.parsers.expat
from pathlib import Path

from . import inventory
from .graph.model import Diagnostic
from .launch.packages import package_xml_files, setup_entry_points
from .launch.xml_front import MAX_XML_DEPTH, XmlRefused, safe_parser
from .safe_io import MAX_SOURCE_BYTES, SKIP_DIRS, describe, is_regular_file, read_bytes, read_text

#: Entry point groups that name executables, not classes a framework instantiates.
SCRIPT_GROUPS = frozenset({"console_scripts", "gui_scripts"})
#: ``plugin="${prefix}/plugin.xml"`` in a package.xml export.
_EXPORTED_PLUGIN = re.compile(r"""\bplugin\s*=\s*["']\$\{prefix\}/([^"'$]+)["']""")
_DOTTED = re.compile(r"^[A-Za-z_][\w.]*$")
#: Robot description files that may declare webots_ros2_driver plugins.
_DESCRIPTION_SUFFIXES = (".urdf", ".xacro")
_IMPORT = r'(?:pybind11|py)::module_?::import\(\s*"([A-Za-z_][\w.]*)"\s*\)'
#: ``auto m = py::module::import("pkg.module");``
_PY_MODULE_VAR = re.compile(r"\b(\w+)\s*=\s*" + _IMPORT)
#: ``m.attr("Class")(`` and ``py::module::import("pkg.module").attr("Class")(``: a call.
_PY_ATTR_CALL = re.compile(r'(?:\b(\w+)|' + _IMPORT + r')\s*\.\s*attr\(\s*"([A-Za-z_]\w*)"\s*\)\s*\(')


def registered_classes(root: Path) -> tuple[dict[str, str], list[Diagnostic]]:
    """``module.Class`` of every class the packages under ``root`` register with a framework,
    mapped to the base class type its ``plugin.xml`` registration writes (``""`` for none), in
    name order; and a diagnostic per package whose metadata could not be read (it registers
    nothing then; its code is still analysed)."""
    found: set[str] = set()
    base_types: dict[str, str] = {}
    diagnostics: list[Diagnostic] = []
    for manifest in package_xml_files(root):
        folder = manifest.parent
        try:
            found.update(_entry_point_targets(folder, root))
            for written, base_type in _plugin_classes(manifest, folder, root):
                found.add(written)
                if base_type:
                    base_types.setdefault(written, base_type)
            found.update(_robot_description_plugins(folder, root))
            found.update(_embedded_python_classes(folder, root))
        except (OSError, UnicodeDecodeError, ValueError, RecursionError, MemoryError, XmlRefused,
                xml.parsers.expat.ExpatError) as exc:
            where = manifest.relative_to(root).as_posix() if manifest.is_relative_to(root) else manifest.name
            diagnostics.append(Diagnostic(where, 1, "classes this package registers with a framework "
                                                    f"(entry points, plugin.xml, robot descriptions, pybind11) are "
                                                    f"not known: "
                                                    f"{describe(exc)}"))
    return {name: base_types.get(name, "") for name in sorted(found)}, diagnostics


def _entry_point_targets(folder: Path, root: Path) -> list[str]:
    groups: dict[str, list[str]] = {}
    setup = folder / "setup.py"
    if is_regular_file(setup):
        try:
            points = setup_entry_points(ast.parse(read_bytes(setup, root)))
        except SyntaxError:
            points = None
        for group, entries in (points or {}).items():
            if isinstance(group, str) and isinstance(entries, list):
                groups.setdefault(group, []).extend(e for e in entries if isinstance(e, str))
    cfg = folder / "setup.cfg"
    if is_regular_file(cfg):
        parser = configparser.ConfigParser(interpolation=None)
        try:
            parser.read_string(read_text(cfg, root))
        except configparser.Error:
            pass
        else:
            if parser.has_section("options.entry_points"):
                for group, raw in parser.items("options.entry_points"):
                    groups.setdefault(group, []).extend(raw.splitlines())
    pyproject = folder / "pyproject.toml"
    if is_regular_file(pyproject) and sys.version_info >= (3, 11):
        import tomllib

        try:
            table = tomllib.loads(read_text(pyproject, root)).get("project", {}).get("entry-points", {})
        except tomllib.TOMLDecodeError:
            table = {}
        for group, entries in table.items() if isinstance(table, dict) else ():
            if isinstance(entries, dict):
                groups.setdefault(group, []).extend(f"{k} = {v}" for k, v in entries.items() if isinstance(v, str))
    return [target for group, entries in groups.items() if group not in SCRIPT_GROUPS
            for target in map(_target, entries) if target is not None]


def _target(entry: str) -> str | None:
    """``package.module.Class`` of ``name = package.module:Class [extras]``."""
    _, sep, value = entry.partition("=")
    module, colon, attr = value.strip().partition(":")
    attr = attr.strip().split()[0] if attr.strip() else ""
    if not sep or not colon or not _DOTTED.match(module.strip()) or not _DOTTED.match(attr):
        return None
    return f"{module.strip()}.{attr}"


def _plugin_classes(manifest: Path, folder: Path, root: Path) -> list[tuple[str, str]]:
    """``(type, base_class_type)`` of every Python class of the package's plugin descriptions."""
    classes: list[tuple[str, str]] = []
    for relative in sorted(set(_EXPORTED_PLUGIN.findall(read_text(manifest, root)))):
        description = (folder / relative).resolve()
        if not is_regular_file(description) or not description.is_relative_to(folder.resolve()):
            continue
        classes.extend(_class_types(read_text(description, root)))
    return classes


def _class_types(text: str) -> list[tuple[str, str]]:
    """The Python ``type`` of every ``<class>`` in a plugin description file, with its
    ``base_class_type`` (empty when not written)."""
    types: list[tuple[str, str]] = []
    parser = safe_parser()
    depth = [0]

    def start(tag: str, attrs: dict[str, str]) -> None:
        depth[0] += 1
        if depth[0] > MAX_XML_DEPTH:
            raise XmlRefused(f"elements nested deeper than {MAX_XML_DEPTH}")
        written = attrs.get("type", "")
        if tag == "class" and "::" not in written and _DOTTED.match(written):
            types.append((written, attrs.get("base_class_type", "")))

    def end(tag: str) -> None:
        depth[0] -= 1

    parser.StartElementHandler = start
    parser.EndElementHandler = end
    parser.Parse(text, True)
    return types


def _robot_description_plugins(folder: Path, root: Path) -> list[str]:
    """``type`` of every Python ``<plugin>`` inside ``<webots>`` in the package's ``*.urdf`` and
    ``*.xacro`` files (hidden and build folders skipped)."""
    classes: list[str] = []
    for dirpath, dirnames, filenames in inventory.walk(folder):
        dirnames[:] = sorted(d for d in dirnames if d not in SKIP_DIRS and not d.startswith("."))
        for name in sorted(filenames):
            if not name.endswith(_DESCRIPTION_SUFFIXES):
                continue
            try:
                text = read_text(Path(dirpath) / name, root, MAX_SOURCE_BYTES)
                if "webots" in text:
                    classes.extend(_webots_plugin_types(text))
            except (OSError, UnicodeDecodeError, ValueError, RecursionError, XmlRefused,
                    xml.parsers.expat.ExpatError):
                continue  # a description that cannot be read names no plugin; the rest still count
    return classes


def _webots_plugin_types(text: str) -> list[str]:
    types: list[str] = []
    parser = safe_parser()
    stack: list[str] = []

    def start(tag: str, attrs: dict[str, str]) -> None:
        if len(stack) >= MAX_XML_DEPTH:
            raise XmlRefused(f"elements nested deeper than {MAX_XML_DEPTH}")
        written = attrs.get("type", "")
        if tag == "plugin" and "webots" in stack and "::" not in written and "." in written \
                and _DOTTED.match(written):
            types.append(written)
        stack.append(tag)

    def end(tag: str) -> None:
        stack.pop()

    parser.StartElementHandler = start
    parser.EndElementHandler = end
    parser.Parse(text, True)
    return types


def _embedded_python_classes(folder: Path, root: Path) -> list[str]:
    """``module.Class`` of every ``attr("Class")(…)`` call on a module that a C++ file of the
    package imports through pybind11 (``py::module::import``, ``py::module_::import``)."""
    from .cpp import CPP_SUFFIXES

    classes: list[str] = []
    for dirpath, dirnames, filenames in inventory.walk(folder):
        dirnames[:] = sorted(d for d in dirnames if d not in SKIP_DIRS and not d.startswith("."))
        for name in sorted(filenames):
            if os.path.splitext(name)[1] not in CPP_SUFFIXES:
                continue
            try:
                text = read_bytes(Path(dirpath) / name, root, MAX_SOURCE_BYTES).decode("utf-8", "replace")
            except OSError:
                continue  # the C++ front end reports what it cannot read
            if "import(" not in text or ".attr(" not in text:
                continue
            modules = {var: module for var, module in _PY_MODULE_VAR.findall(text)}
            for var, module, attr in _PY_ATTR_CALL.findall(text):
                module = module or modules.get(var, "")
                if module:
                    classes.append(f"{module}.{attr}")
    return classes
