"""Run flake8 in this interpreter, optionally hiding installed distributions from its plugin search.

Why this exists: the benchmark compares flake8 *with* the plugin against flake8
*without* it, on the same interpreter and the same flake8, pycodestyle, pyflakes
and mccabe. flake8 offers no switch that keeps an installed plugin from running:

* ``--select``/``--ignore``/``--extend-ignore`` only filter what is *reported*;
  flake8 4.0.1 (``checker.FileChecker.run_ast_checks``) and 7.x
  (``plugins.finder._classify_plugins`` then ``checker``) still instantiate and
  run every loaded tree plugin on every file;
* ``off_by_default`` plus ``--enable-extensions`` is decided by the plugin's
  author; in flake8 ≥ 5 it skips the plugin, in 4.0.1 it only adds the code to
  the default ignore list, so the plugin still runs.

Both flake8 4.0.1 (``importlib.metadata.entry_points()``) and 7.x
(``importlib.metadata.distributions()``) find plugins through
``importlib.metadata.distributions``, and ``entry_points()`` calls it too. Filtering
that one function before flake8 starts makes the named distributions invisible:
their entry points are never loaded, so none of their code is imported or run.
``run.py`` checks the effect with ``--version``, which lists the loaded plugins.

Usage: ``python flake8_launcher.py [--hide DIST]... [--] FLAKE8_ARGS...``
"""
from __future__ import annotations

import importlib.metadata
import re
import sys
from typing import Iterator


def _canonical(name: str) -> str:
    """PEP 503 normalisation, so ``flake8_rosgraph`` and ``Flake8-RosGraph`` are one name."""
    return re.sub(r"[-_.]+", "-", name).lower()


def hide_distributions(names: list[str]) -> None:
    """Make ``importlib.metadata.distributions`` skip the distributions called ``names``."""
    hidden = {_canonical(name) for name in names}
    if not hidden:
        return
    real = importlib.metadata.distributions

    def visible(**kwargs: object) -> Iterator[importlib.metadata.Distribution]:
        return (dist for dist in real(**kwargs)
                if _canonical(dist.metadata["Name"] or "") not in hidden)

    importlib.metadata.distributions = visible  # type: ignore[assignment]


def split_args(argv: list[str]) -> tuple[list[str], list[str]]:
    """``--hide`` values, and the arguments for flake8."""
    hidden: list[str] = []
    rest = list(argv)
    while len(rest) >= 2 and rest[0] == "--hide":
        hidden.append(rest[1])
        rest = rest[2:]
    if rest[:1] == ["--"]:
        rest = rest[1:]
    return hidden, rest


def main(argv: list[str]) -> int:
    hidden, flake8_args = split_args(argv)
    hide_distributions(hidden)
    from flake8.main.cli import main as flake8_main

    return int(flake8_main(flake8_args) or 0)


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
