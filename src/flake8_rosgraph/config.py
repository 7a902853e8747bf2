"""The configuration files ``check`` reads, so that it and the flake8 plugin agree.

The plugin gets its options from flake8, which reads the ``[flake8]`` section
of the first ``setup.cfg``, ``tox.ini`` or ``.flake8`` found from the current
folder upwards. ``check`` reads that same section the same way (its
``rosgraph-*`` keys, ``select``, ``extend-select``, ``ignore``,
``extend-ignore`` and ``per-file-ignores``), and in addition the
``[tool.flake8-rosgraph]`` table of the nearest ``pyproject.toml`` (flake8
itself does not read ``pyproject.toml``). Precedence: a command-line flag,
then ``pyproject.toml``, then ``[flake8]``, then the ``ROSGRAPH_*``
environment variables. Paths in a file are relative to that file's folder.

A value that cannot be right (an unknown key in our own table, a number where
a list of codes belongs) is a :class:`ConfigError` naming the file and key;
unknown keys of ``[flake8]`` belong to other plugins and are left alone.
"""
from __future__ import annotations

import configparser
import fnmatch
import os
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover - Python 3.10
    import tomli as tomllib

#: Settings that hold a path or a list of paths (made absolute against the file's folder).
PATH_SETTINGS = frozenset({"root", "sarif", "cache_dir", "baseline"})
PATHS_SETTINGS = frozenset({"stubs", "interfaces"})
#: Settings that hold a list of names or codes.
LIST_SETTINGS = frozenset({"external_topics", "select", "extend_select", "ignore", "extend_ignore"})
BOOL_SETTINGS = frozenset({"debug"})
#: ``[flake8]`` key → setting.
FLAKE8_KEYS: dict[str, str] = {
    "rosgraph-root": "root", "rosgraph-stubs": "stubs", "rosgraph-external-topics": "external_topics",
    "rosgraph-sarif": "sarif", "rosgraph-cache-dir": "cache_dir", "rosgraph-debug": "debug",
    "rosgraph-interfaces": "interfaces",
    "select": "select", "extend-select": "extend_select", "ignore": "ignore",
    "extend-ignore": "extend_ignore", "per-file-ignores": "per_file_ignores",
}
#: ``[tool.flake8-rosgraph]`` key → setting.
PYPROJECT_KEYS: dict[str, str] = {
    "root": "root", "stubs": "stubs", "external-topics": "external_topics", "sarif": "sarif",
    "cache-dir": "cache_dir", "debug": "debug", "select": "select", "extend-select": "extend_select",
    "ignore": "ignore", "extend-ignore": "extend_ignore", "per-file-ignores": "per_file_ignores",
    "baseline": "baseline", "interfaces": "interfaces",
}
_TRUE = {"1", "true", "yes", "on"}
_FALSE = {"0", "false", "no", "off", ""}


class ConfigError(Exception):
    """A configuration value that cannot be used; the message names the file and the key."""


@dataclass(frozen=True)
class PerFileIgnore:
    """Codes not reported in the files a pattern matches (flake8's ``per-file-ignores``)."""

    pattern: str
    codes: tuple[str, ...]
    base: Path

    def matches(self, path: Path) -> bool:
        pattern = self.pattern
        if "/" in pattern:
            pattern = os.path.normpath(os.path.join(self.base, pattern))
            return fnmatch.fnmatch(str(path), pattern)
        return fnmatch.fnmatch(path.name, pattern) or fnmatch.fnmatch(str(path), pattern)


@dataclass(frozen=True)
class FileConfig:
    """The settings the configuration files give (absent keys are absent), and the files read."""

    values: dict[str, Any] = field(default_factory=dict)
    per_file_ignores: tuple[PerFileIgnore, ...] = ()
    files: tuple[Path, ...] = ()

    def ignored_in(self, path: Path, code: str) -> bool:
        return any(entry.matches(path) and code.startswith(entry.codes) for entry in self.per_file_ignores)


def _split(value: str) -> list[str]:
    return [item.strip() for item in value.replace("\n", ",").split(",") if item.strip()]


def _flake8_file(start: Path) -> Path | None:
    """The file flake8 would read: the first with a ``[flake8]`` section, from ``start`` upwards."""
    for folder in [start, *start.parents]:
        for name in ("setup.cfg", "tox.ini", ".flake8"):
            candidate = folder / name
            if not candidate.is_file():
                continue
            parser = configparser.RawConfigParser()
            try:
                parser.read(candidate, encoding="utf-8")
            except (UnicodeDecodeError, configparser.Error):
                continue  # flake8 ignores an unparsable file too
            if parser.has_section("flake8"):
                return candidate
        if (folder / ".git").exists():
            break  # never look above the repository the user is in
    return None


def _pyproject(start: Path) -> Path | None:
    for folder in [start, *start.parents]:
        if (folder / "pyproject.toml").is_file():
            return folder / "pyproject.toml"
        if (folder / ".git").exists():
            break
    return None


def _convert(setting: str, raw: Any, base: Path, where: str) -> Any:
    if setting in BOOL_SETTINGS:
        if isinstance(raw, bool):
            return raw
        if isinstance(raw, str) and raw.strip().lower() in _TRUE | _FALSE:
            return raw.strip().lower() in _TRUE
        raise ConfigError(f"{where}: expected true or false, got {raw!r}")
    if isinstance(raw, str):
        items = _split(raw)
    elif isinstance(raw, list) and all(isinstance(item, str) for item in raw):
        items = [item.strip() for item in raw if item.strip()]
    else:
        raise ConfigError(f"{where}: expected a string or a list of strings, got {raw!r}")
    if setting in PATH_SETTINGS:
        if len(items) != 1:
            raise ConfigError(f"{where}: expected one path, got {raw!r}")
        return str(base / items[0])
    if setting in PATHS_SETTINGS:
        return [str(base / item) for item in items]
    if setting in ("select", "extend_select", "ignore", "extend_ignore"):
        bad = [code for code in items if not code.replace("_", "").isalnum()]
        if bad:
            raise ConfigError(f"{where}: not a code or code prefix: {', '.join(bad)}")
        return [code.upper() for code in items]
    return items


def _per_file_ignores(raw: Any, base: Path, where: str) -> list[PerFileIgnore]:
    from flake8.utils import parse_files_to_codes_mapping

    if isinstance(raw, dict):
        pairs = [(pattern, _convert("ignore", codes, base, f"{where}.{pattern}")) for pattern, codes in raw.items()]
    elif isinstance(raw, str):
        try:
            pairs = [(pattern, [c.upper() for c in codes]) for pattern, codes in parse_files_to_codes_mapping(raw)]
        except ValueError as exc:
            raise ConfigError(f"{where}: {exc}") from None
    else:
        raise ConfigError(f"{where}: expected 'pattern: codes' lines or a table, got {raw!r}")
    return [PerFileIgnore(pattern, tuple(codes), base) for pattern, codes in pairs if codes]


def load_config(start: Path) -> FileConfig:
    """The settings of the configuration files that apply in folder ``start``."""
    values: dict[str, Any] = {}
    ignores: list[PerFileIgnore] = []
    files: list[Path] = []
    flake8_file = _flake8_file(start)
    if flake8_file is not None:
        files.append(flake8_file)
        parser = configparser.RawConfigParser()
        parser.read(flake8_file, encoding="utf-8")
        for key, raw in parser.items("flake8"):
            setting = FLAKE8_KEYS.get(key.replace("_", "-"))
            where = f"{flake8_file}: [flake8] {key}"
            if setting == "per_file_ignores":
                ignores += _per_file_ignores(raw, flake8_file.parent, where)
            elif setting is not None:
                values[setting] = _convert(setting, raw, flake8_file.parent, where)
    pyproject = _pyproject(start)
    if pyproject is not None:
        try:
            table = tomllib.loads(pyproject.read_text(encoding="utf-8")).get("tool", {}).get("flake8-rosgraph")
        except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError) as exc:
            raise ConfigError(f"{pyproject}: cannot read: {exc}") from None
        if table is not None:
            files.append(pyproject)
            if not isinstance(table, dict):
                raise ConfigError(f"{pyproject}: [tool.flake8-rosgraph] must be a table")
            for key, raw in table.items():
                where = f"{pyproject}: [tool.flake8-rosgraph] {key}"
                setting = PYPROJECT_KEYS.get(key)
                if setting is None:
                    raise ConfigError(f"{where}: unknown key (known: {', '.join(sorted(PYPROJECT_KEYS))})")
                if setting == "per_file_ignores":
                    ignores = _per_file_ignores(raw, pyproject.parent, where)
                else:
                    values[setting] = _convert(setting, raw, pyproject.parent, where)
    return FileConfig(values, tuple(ignores), tuple(files))
