"""Finding the launch files of a workspace and reading each with its front end.

Python launch files are the analysed modules that define a module-level
``generate_launch_description``; XML and YAML ones are ``*.xml``/``*.yaml``
files whose name says ``launch`` or that sit in a ``launch`` folder, and whose
content is a ``<launch>`` element or a top-level ``launch:`` list.
"""
from __future__ import annotations

import xml.parsers.expat
from pathlib import Path
from typing import Mapping

from .. import inventory
from ..absint.engine import Analysis
from ..graph.model import Diagnostic
from ..safe_io import describe, is_within, read_text
from ..workspace import SKIP_DIRS, left_out
from .actions import Action
from .python_front import ENTRY_FUNCTION, read_python_launch
from .xml_front import XmlRefused, parse_xml, read_xml_launch
from .yaml_front import read_yaml_launch
from .yaml_reader import YamlError

FRONTEND_SUFFIXES = (".xml", ".yaml", ".yml")


def python_launch_files(analysis: Analysis | None) -> list[str]:
    if analysis is None:
        return []
    return sorted({f.module.path for f in analysis.program.functions
                   if f.parent is None and f.cls is None and f.qualname == ENTRY_FUNCTION})


def _looks_like_launch(path: Path, root: Path, diagnostics: list[Diagnostic]) -> bool:
    rel = path.relative_to(root).as_posix()
    try:
        text = read_text(path, root)
    except (OSError, UnicodeDecodeError) as exc:
        diagnostics.append(Diagnostic(rel, 1, f"launch file candidate not read: {describe(exc)}"))
        return False
    if path.suffix == ".xml":
        try:
            return parse_xml(text).tag == "launch"
        except (xml.parsers.expat.ExpatError, XmlRefused, IndexError) as exc:
            if path.name.endswith(".launch.xml"):
                diagnostics.append(Diagnostic(rel, getattr(exc, "lineno", 1) or 1,
                                              f"launch file not read: XML error: {exc}"))
            return False
    return any(line.rstrip() == "launch:" for line in text.splitlines())


def frontend_launch_files(root: Path, diagnostics: list[Diagnostic] | None = None) -> list[str]:
    """XML/YAML launch files under ``root``; what cannot be read becomes one of ``diagnostics``."""
    diagnostics = [] if diagnostics is None else diagnostics
    found: list[str] = []
    if not root.is_dir():
        return found

    def unreadable(error: OSError) -> None:
        where = Path(error.filename or root)
        rel = where.relative_to(root).as_posix() if is_within(where, root) else where.name
        diagnostics.append(Diagnostic(rel, 1, f"folder not read, launch files in it are not analysed: "
                                              f"{error.strerror or error}"))

    for dirpath, dirnames, filenames in inventory.walk(root, unreadable):
        why = left_out(Path(dirpath), filenames, root)
        if why is not None:
            dirnames[:] = []
            diagnostics.append(why)
            continue
        dirnames[:] = sorted(d for d in dirnames if d not in SKIP_DIRS and not d.startswith("."))
        in_launch_dir = Path(dirpath).name == "launch"
        for name in sorted(filenames):
            path = Path(dirpath) / name
            if path.suffix in FRONTEND_SUFFIXES and ("launch" in name or in_launch_dir) \
                    and _looks_like_launch(path, root, diagnostics):
                found.append(path.relative_to(root).as_posix())
    return sorted(found)


#: A Python launch file's actions (or why there are none), by root-relative path.
PythonLaunches = Mapping[str, tuple[list[Action], "str | None"]]


def read_python_launches(analysis: Analysis) -> dict[str, tuple[list[Action], str | None]]:
    """The actions of every Python launch file of ``analysis``, read while its heap is there.
    One file that cannot be read costs that file only."""
    out = {}
    for path in python_launch_files(analysis):
        try:
            out[path] = read_python_launch(analysis, path)
        except Exception as exc:
            out[path] = [], f"internal error: {type(exc).__name__}: {exc}"[:300]
    return out


class LaunchReader:
    """Reads any launch file by extension, once; Python ones from ``python``, what the analysis
    read of them (``None``: the Python code was not analysed)."""

    def __init__(self, root: Path, python: PythonLaunches | None) -> None:
        self.root = Path(root)
        self.python = python
        self._cache: dict[str, tuple[list[Action], str | None]] = {}

    def __call__(self, path: str) -> tuple[list[Action], str | None]:
        if path not in self._cache:
            self._cache[path] = self._read(path)
        return self._cache[path]

    def _read(self, path: str) -> tuple[list[Action], str | None]:
        if path.endswith(".py"):
            if self.python is None:
                return [], "Python launch files need the analysis"
            return self.python.get(path) or ([], f"no {ENTRY_FUNCTION}() function")
        try:
            text = read_text(self.root / path, self.root)
        except (OSError, UnicodeDecodeError) as exc:
            return [], f"cannot read: {describe(exc)}"
        try:
            if path.endswith(".xml"):
                return read_xml_launch(path, text), None
            if path.endswith((".yaml", ".yml")):
                return read_yaml_launch(path, text), None
        except xml.parsers.expat.ExpatError as exc:
            return [], f"XML error: {exc}"
        except XmlRefused as exc:
            return [], f"XML refused: {exc}"
        except YamlError as exc:
            return [], f"YAML error: {exc}"
        except IndexError:
            return [], "empty XML document"
        return [], "not a launch file format this tool reads"
