"""Which message definitions the analysis knows, and how a Python class name maps to one.

Three sources, later ones winning: the standard packages shipped as generated facts
(``standard.json``), interface folders the user names (``--rosgraph-interfaces``), and the
packages of the workspace itself (a folder with a ``package.xml`` and ``msg/``, ``srv/`` or
``action/`` files). Files are read like Python sources are: regular files only, size-limited,
never following links out of the folder; a file that does not parse costs only itself and
becomes a diagnostic.
"""
from __future__ import annotations

import json
import re
import stat
from dataclasses import dataclass, field
from importlib.resources import files
from pathlib import Path
from typing import Iterable

from .. import inventory
from .definitions import PARTS, InterfaceError, MessageDef, parse_interface, parse_message

#: Interface files larger than this are skipped (the biggest standard one is a few KiB).
MAX_INTERFACE_BYTES = 256 * 1024
#: Interface files read from one folder tree before the rest is skipped.
MAX_INTERFACE_FILES = 5000
_SKIP_DIRS = frozenset({"build", "install", "log", "__pycache__", "node_modules"})
_PACKAGE_NAME = re.compile(r"<name>\s*([A-Za-z][\w]*)\s*</name>")
_KINDS = tuple(PARTS)

#: ``pkg.msg.Name``, ``pkg.msg._name.Name``, ``pkg.srv.Name.Request``, ``pkg.action.Name.Goal``.
_PY_CLASS = re.compile(
    r"^(?P<pkg>[A-Za-z_]\w*)\.(?P<kind>msg|srv|action)(?:\._\w+)?\.(?P<name>[A-Za-z]\w*)"
    r"(?:\.(?P<part>Request|Response|Goal|Result|Feedback))?$")


def message_key(qualname: str) -> str | None:
    """The definition key of a generated Python message class (``std_msgs.msg.String`` →
    ``std_msgs/msg/String``, ``std_srvs.srv.SetBool.Response`` → ``std_srvs/srv/SetBool_Response``);
    ``None`` for anything else, including a service or action class itself."""
    match = _PY_CLASS.match(qualname)
    if match is None:
        return None
    kind, name, part = match.group("kind"), match.group("name"), match.group("part")
    if kind == "msg":
        return None if part else f"{match.group('pkg')}/msg/{name}"
    if part is None:
        suffix = next((s for s in PARTS[kind] if name.endswith(s)), None)
        return f"{match.group('pkg')}/{kind}/{name}" if suffix else None
    if "_" + part not in PARTS[kind]:
        return None
    return f"{match.group('pkg')}/{kind}/{name}_{part}"


def generated_class_identity(qualname: str) -> tuple[str, str] | None:
    """``(__module__, __name__)`` of the Python class rosidl generates for a message type:
    ``nav_msgs.msg.Path`` → ``("nav_msgs.msg._path", "Path")``, ``std_srvs.srv.SetBool.Response``
    → ``("std_srvs.srv._set_bool", "SetBool_Response")``; ``None`` for anything else.

    Generic code often dispatches on these (``msg.__module__ == "sensor_msgs.msg._image"``,
    ``type(msg).__name__ == "Image"``); knowing them keeps a message off the branches written
    for other types."""
    key = message_key(qualname)
    if key is None:
        return None
    package, kind, name = key.split("/")
    base = next((name[:-len(s)] for s in PARTS[kind] if s and name.endswith(s)), name)
    return f"{package}.{kind}._{_snake_case(base)}", name


def _snake_case(name: str) -> str:
    """rosidl's module name for a type name (``PointCloud2`` → ``point_cloud2``)."""
    name = re.sub(r"(.)([A-Z][a-z]+)", r"\1_\2", name)
    return re.sub(r"([a-z0-9])([A-Z])", r"\1_\2", name).lower()


def display_name(key: str) -> str:
    """``std_srvs/srv/SetBool_Response`` → ``std_srvs/srv/SetBool.Response`` (as code names it)."""
    pkg, kind, name = key.split("/", 2)
    for suffix in PARTS[kind]:
        if suffix and name.endswith(suffix):
            return f"{pkg}/{kind}/{name[:-len(suffix)]}.{suffix[1:]}"
    return key


@dataclass
class Catalogue:
    """Message definitions by key, plus the problems met while reading them."""

    messages: dict[str, MessageDef] = field(default_factory=dict)
    problems: list[tuple[str, str]] = field(default_factory=list)  # (path, message)

    def get(self, key: str | None) -> MessageDef | None:
        return self.messages.get(key) if key is not None else None

    def add_text(self, text: str, package: str, kind: str, name: str, where: str) -> None:
        try:
            for definition in parse_interface(text, package, kind, name):
                self.messages[definition.key] = definition
        except InterfaceError as exc:
            self.problems.append((where, f"interface file not read: {exc}"))

    def add_tree(self, folder: Path, root: Path | None = None) -> None:
        """Every package (a folder with ``package.xml``) under ``folder`` and its interface files."""
        self.add_files(interface_files(folder, root))

    def add_files(self, found: Iterable[InterfaceFile]) -> None:
        """The definitions of ``found`` (later ones winning), and the problems of those not read."""
        for file in found:
            if file.text is None:
                self.problems.append((file.shown, file.problem))
            else:
                self.add_text(file.text, file.package, file.kind, file.name, file.shown)


@dataclass(frozen=True)
class InterfaceFile:
    """One interface file of a package as read, or why it was not: what the workspace's
    metadata keeps (:mod:`flake8_rosgraph.metadata`), so that a run after a Python edit
    does not walk the workspace for them again."""

    package: str
    kind: str
    name: str
    shown: str          # the path diagnostics name
    text: str | None
    problem: str = ""   # why ``text`` is None


def interface_files(folder: Path, root: Path | None = None) -> list[InterfaceFile]:
    """The interface files of every package under ``folder``, in path order (see :meth:`Catalogue.add_tree`)."""
    found: list[InterfaceFile] = []
    for package_dir, package in _packages(folder):
        for kind in _KINDS:
            sub = package_dir / kind
            if not sub.is_dir() or sub.is_symlink():
                continue
            for path in sorted(sub.iterdir()):
                if path.suffix != "." + kind or not _NAME_OK.match(path.stem):
                    continue
                if len(found) >= MAX_INTERFACE_FILES:
                    found.append(InterfaceFile(package, kind, path.stem, _shown(path, root), None,
                                               f"more than {MAX_INTERFACE_FILES} interface files; "
                                               "the rest are not read"))
                    return found
                text = _read(path)
                found.append(InterfaceFile(package, kind, path.stem, _shown(path, root), text,
                                           "" if text is not None else "interface file not read: not a "
                                           f"regular file, or larger than {MAX_INTERFACE_BYTES} bytes"))
    return found


_NAME_OK = re.compile(r"^[A-Z][A-Za-z0-9]*$")


def _shown(path: Path, root: Path | None) -> str:
    if root is not None:
        try:
            return path.relative_to(root).as_posix()
        except ValueError:
            pass
    return path.as_posix()


def _read(path: Path) -> str | None:
    try:
        info = path.lstat()
        if not stat.S_ISREG(info.st_mode) or info.st_size > MAX_INTERFACE_BYTES:
            return None
        with path.open("rb") as handle:
            data = handle.read(MAX_INTERFACE_BYTES + 1)
        if len(data) > MAX_INTERFACE_BYTES:
            return None
        return data.decode("utf-8", errors="replace")
    except OSError:
        return None


def _packages(folder: Path) -> Iterable[tuple[Path, str]]:
    """``(folder, package name)`` of every package.xml under ``folder``, in path order."""
    if not folder.is_dir():
        return
    for dirpath, dirnames, filenames in inventory.walk(folder):
        dirnames[:] = sorted(d for d in dirnames if d not in _SKIP_DIRS and not d.startswith("."))
        if "COLCON_IGNORE" in filenames or "AMENT_IGNORE" in filenames:
            dirnames[:] = []
            continue
        if "package.xml" in filenames:
            text = _read(Path(dirpath) / "package.xml") or ""
            match = _PACKAGE_NAME.search(text)
            yield Path(dirpath), match.group(1) if match else Path(dirpath).name


def standard_catalogue() -> Catalogue:
    """The shipped definitions of the standard interface packages."""
    data = json.loads(files("flake8_rosgraph.interfaces").joinpath("standard.json")
                      .read_text(encoding="utf-8"))
    catalogue = Catalogue()
    for key, lines in data["messages"].items():
        catalogue.messages[key] = parse_message("\n".join(lines), key)
    return catalogue


def load_catalogue(root: Path | None, extra: Iterable[Path] = (),
                   workspace: Iterable[InterfaceFile] | None = None) -> Catalogue:
    """Standard definitions, then the user's interface folders, then the workspace's own
    (``workspace``: those files as read before, else read from ``root`` now)."""
    catalogue = standard_catalogue()
    for folder in extra:
        catalogue.add_tree(Path(folder))
    if workspace is not None:
        catalogue.add_files(workspace)
    elif root is not None and Path(root).is_dir():
        catalogue.add_tree(Path(root), Path(root))
    return catalogue
