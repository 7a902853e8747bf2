"""The user's settings, from flake8 options, config files and environment variables.

Every option exists twice: as a flake8 option (command line and the ``[flake8]``
section of ``setup.cfg`` / ``tox.ini`` / ``.flake8``) and as an environment
variable, because ``ament_flake8`` runs flake8 with its own config file and
never reads the project's. An option given to flake8 (command line or config)
wins over the environment variable; list values are comma-separated in both.

======================== ============================ =========================================
flake8 option            environment variable         meaning
======================== ============================ =========================================
``--rosgraph-root``      ``ROSGRAPH_ROOT``            workspace root (default: discovered)
``--rosgraph-stubs``     ``ROSGRAPH_STUBS``           extra library model files (``*.toml``)
``--rosgraph-external-   ``ROSGRAPH_EXTERNAL_TOPICS`` names handled outside the workspace,
topics``                                              on top of the built-in exempt list
``--rosgraph-sarif``     ``ROSGRAPH_SARIF``           also write a SARIF file of the run
``--rosgraph-            ``ROSGRAPH_INTERFACES``      folders of interface packages outside
interfaces``                                          the workspace, for ROS104/ROS107
``--rosgraph-cache-dir`` ``ROSGRAPH_CACHE_DIR``       cache location (default:
                                                      ``<root>/.rosgraph-cache``)
``--rosgraph-debug``     ``ROSGRAPH_DEBUG``           re-raise internal errors
======================== ============================ =========================================

Off-by-default rules (ROS010) are reported only when a ``--select``,
``--extend-select`` or ``--enable-extensions`` entry names them *specifically*:
an entry that is a prefix of the rule's code and of no default-enabled rule's
code (``ROS010``, ``ROS01``). Family selectors such as ``ROS`` or ``ROS0`` mean
"the ROS rules" and keep the default set, so ``flake8 --select ROS`` does not
start printing coverage notes. flake8 itself has no per-code default-off for
plugins (``off_by_default`` switches a whole entry point), so the plugin does
this filtering before flake8's own select/ignore logic runs. One limit:
flake8 ≥ 5 consumes ``--enable-extensions`` given *on the command line* while
loading plugins and never shows it to them, so there it counts only from
config files; ``--extend-select ROS010`` works everywhere.
"""
from __future__ import annotations

import argparse
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Iterable, Mapping, Sequence

#: Unsaved editor buffers: absolute file path → the buffer's bytes, analysed instead of the file on disk.
Buffers = tuple[tuple[str, bytes], ...]
#: The code reported instead of a crash (flake8 plugin and ``check`` command alike).
INTERNAL_ERROR_CODE = "ROS000"
#: Environment variables, by setting name.
ENV_VARS: dict[str, str] = {
    "root": "ROSGRAPH_ROOT",
    "stubs": "ROSGRAPH_STUBS",
    "external_topics": "ROSGRAPH_EXTERNAL_TOPICS",
    "sarif": "ROSGRAPH_SARIF",
    "cache_dir": "ROSGRAPH_CACHE_DIR",
    "debug": "ROSGRAPH_DEBUG",
    "interfaces": "ROSGRAPH_INTERFACES",
}
TRUE_WORDS = frozenset({"1", "true", "yes", "on"})


@dataclass(frozen=True)
class Settings:
    """What the plugin and the ``check`` command need to know, whatever the source."""

    root: Path | None = None
    stub_files: tuple[Path, ...] = ()
    external_topics: tuple[str, ...] = ()
    sarif: Path | None = None
    cache_dir: Path | None = None
    debug: bool = False
    interface_dirs: tuple[Path, ...] = ()

    @classmethod
    def resolve(cls, given: Mapping[str, Any], environ: Mapping[str, str]) -> Settings:
        """Merge explicitly given values (``None`` = not given) with the environment."""

        def pick(name: str) -> Any:
            value = given.get(name)
            if value is None or value == []:
                value = environ.get(ENV_VARS[name]) or None
            return value

        return cls(
            root=_path(pick("root")),
            stub_files=tuple(Path(p) for p in _names(pick("stubs"))),
            external_topics=tuple(_names(pick("external_topics"))),
            sarif=_path(pick("sarif")),
            cache_dir=_path(pick("cache_dir")),
            debug=bool(given.get("debug")) or environ.get(ENV_VARS["debug"], "").strip().lower() in TRUE_WORDS,
            interface_dirs=tuple(Path(p) for p in _names(pick("interfaces"))),
        )

    @classmethod
    def from_flake8(cls, options: argparse.Namespace, environ: Mapping[str, str] = os.environ) -> Settings:
        """Settings from flake8's parsed options (see :func:`register_flake8_options`)."""
        given = {name: getattr(options, f"rosgraph_{name}", None) for name in ENV_VARS}
        return cls.resolve(given, environ)


def _names(value: str | Sequence[str] | None) -> list[str]:
    if value is None:
        return []
    items = value.split(",") if isinstance(value, str) else list(value)
    return [item.strip() for item in items if item.strip()]


def _path(value: str | None) -> Path | None:
    return Path(value) if value else None


def root_problem(root: Path | None, option: str, given: Any = None) -> str | None:
    """Why an explicitly given workspace root cannot be used (``None``: it can, or none was given)."""
    if root is None:
        return None
    source = option if getattr(given, option.lstrip("-").replace("-", "_"), None) else ENV_VARS["root"]
    if not root.exists():
        return f"{source}: no such folder: {root}"
    if not root.is_dir():
        return f"{source}: not a folder: {root}"
    return None


def register_flake8_options(parser: Any) -> None:
    """Add the ``--rosgraph-*`` options to flake8's option manager (flake8 4.0.1 … 7.x)."""
    parser.add_option(
        "--rosgraph-root", default=None, parse_from_config=True, normalize_paths=True,
        help="ROS workspace to analyse (default: the colcon workspace or version-control "
             "root above each checked file). Env: ROSGRAPH_ROOT.",
    )
    parser.add_option(
        "--rosgraph-stubs", default=None, parse_from_config=True, comma_separated_list=True,
        normalize_paths=True,
        help="Comma-separated extra library model files (TOML). Env: ROSGRAPH_STUBS.",
    )
    parser.add_option(
        "--rosgraph-external-topics", default=None, parse_from_config=True, comma_separated_list=True,
        help="Comma-separated topic/service/action names used outside the workspace "
             "(wildcards * ? **), added to the built-in exempt list. Env: ROSGRAPH_EXTERNAL_TOPICS.",
    )
    parser.add_option(
        "--rosgraph-sarif", default=None, parse_from_config=True, normalize_paths=True,
        help="Also write everything flake8 reports to this SARIF 2.1.0 file. Env: ROSGRAPH_SARIF.",
    )
    parser.add_option(
        "--rosgraph-cache-dir", default=None, parse_from_config=True, normalize_paths=True,
        help="Where to keep the workspace analysis cache (default: <root>/.rosgraph-cache). "
             "Env: ROSGRAPH_CACHE_DIR.",
    )
    parser.add_option(
        "--rosgraph-interfaces", default=None, parse_from_config=True, comma_separated_list=True,
        normalize_paths=True,
        help="Comma-separated folders of interface packages (package.xml with msg/, srv/, "
             "action/) outside the workspace, for the message rules. Env: ROSGRAPH_INTERFACES.",
    )
    parser.add_option(
        "--rosgraph-debug", default=False, action="store_true", parse_from_config=True,
        help="Re-raise internal errors of flake8-rosgraph instead of reporting ROS000. "
             "Env: ROSGRAPH_DEBUG=1.",
    )


@dataclass(frozen=True)
class CodeFilter:
    """Which codes a front end hands on: every default-enabled one, plus the opted-in off-by-default ones."""

    default_off: frozenset[str] = frozenset()
    opted_in: frozenset[str] = frozenset()

    @classmethod
    def build(cls, selectors: Iterable[str], rules: Iterable[Any]) -> CodeFilter:
        """Opt in the off-by-default rules that some selector names specifically (see module docstring)."""
        rules = list(rules)
        default_codes = [rule.code for rule in rules if rule.default_enabled]
        default_off = frozenset(rule.code for rule in rules if not rule.default_enabled)
        opted_in: set[str] = set()
        for selector in (s.strip().upper() for s in selectors):
            if selector and not any(code.startswith(selector) for code in default_codes):
                opted_in.update(code for code in default_off if code.startswith(selector))
        return cls(default_off, frozenset(opted_in))

    def __call__(self, code: str) -> bool:
        return code not in self.default_off or code in self.opted_in


def flake8_selectors(options: argparse.Namespace) -> list[str]:
    """The entries of ``--select``, ``--extend-select`` and ``--enable-extensions``.

    flake8 ≥ 5 reads ``enable-extensions`` before loading plugins and leaves it
    out of ``options``; its config-file value is read here the way flake8 reads it.
    """
    selectors: list[str] = []
    for name in ("select", "extend_select"):
        selectors += _names(getattr(options, name, None))
    selectors += _enable_extensions(options)
    return selectors


def _enable_extensions(options: argparse.Namespace) -> list[str]:
    value = getattr(options, "enable_extensions", None)
    if isinstance(value, list):  # flake8 4: a regular, config-aware option
        return _names(value)
    try:
        from flake8.options.config import load_config
        from flake8.plugins.finder import parse_plugin_options
    except ImportError:
        return _names(value)
    cfg, cfg_dir = load_config(
        config=getattr(options, "config", None),
        extra=list(getattr(options, "append_config", None) or []),
        isolated=bool(getattr(options, "isolated", False)),
    )
    plugin_options = parse_plugin_options(cfg, cfg_dir, enable_extensions=value, require_plugins=None)
    return sorted(plugin_options.enable_extensions)
