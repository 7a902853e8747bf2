"""Which findings a run shows when it checks only some files of the workspace.

pre-commit hooks and pull-request checks run flake8 on the changed files
only. A broken connection has two ends in two files, and its finding sits at
one of them (the side most likely wrong); when only the other file changed,
the finding would vanish from the run that matters. So when the end a finding
sits at is not checked, a copy is shown at each checked file holding one of
its other ends (its related locations), pointing back. In a full run every
file is checked and each problem is shown once, where the rule put it.

Kept outside the ``rules`` package (like :mod:`.findings`): the flake8
plugin's warm path uses it on findings read back from the cache.
"""
from __future__ import annotations

import fnmatch
import os
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Iterable

from .findings import Finding

#: Codes whose related locations are the other ends of a broken connection:
#: a near miss (ROS001/ROS003/ROS008/ROS009), a type mismatch (ROS004), a QoS mismatch (ROS005).
CONNECTION_CODES = frozenset({"ROS001", "ROS003", "ROS004", "ROS005", "ROS008", "ROS009"})


def mirrored(finding: Finding, at: tuple) -> Finding:
    """``finding`` shown at its other end ``at`` (a related location), pointing back to where it belongs."""
    location, _ = at
    message = f"{finding.message} (reported at {finding.location.short()}, which this run does not check)"
    others = tuple(r for r in finding.related if r[0] != location)
    return Finding(location, finding.code, message, ((finding.location, "where the rule reports it"), *others))


def shown_findings(findings: Iterable[Finding], checked: Callable[[str], bool]) -> list[Finding]:
    """The findings located in checked files, plus a mirror of each broken connection whose end is unchecked.

    ``checked`` takes a root-relative path. A mirror is placed at the first
    related location of each checked file (one per file), unless a finding
    shown there already names the unchecked end (both ends of a near miss
    dangle: each is reported, pointing at the other). A full run, where
    every file is checked, shows exactly ``findings``.
    """
    findings = list(findings)
    shown = [f for f in findings if checked(f.location.path)]
    told = {(f.location, other) for f in shown for other, _ in f.related}
    for finding in findings:
        if finding.code not in CONNECTION_CODES or checked(finding.location.path):
            continue
        files: set[str] = set()
        for other in finding.related:
            location = other[0]
            if location.path not in files and checked(location.path) and (location, finding.location) not in told:
                files.add(location.path)
                shown.append(mirrored(finding, other))
    return shown


@dataclass(frozen=True)
class CheckedFiles:
    """The files a flake8 run checks: the paths it was given, as flake8 expands them.

    A given file is checked; a file under a given folder when it matches the
    ``--filename`` patterns and neither it nor a folder on the way is
    excluded (``--exclude``/``--extend-exclude``: a pattern matches the base
    name or the absolute path, as in flake8).
    """

    targets: tuple[str, ...]
    exclude: tuple[str, ...] = ()
    patterns: tuple[str, ...] = ("*.py",)

    @classmethod
    def from_flake8(cls, options: object) -> CheckedFiles | None:
        """What ``options`` ask flake8 to check; ``None`` (everything) when flake8 does not say, or for stdin."""
        filenames = getattr(options, "filenames", None)
        if filenames is None or "-" in filenames:
            return None
        exclude = (*(getattr(options, "exclude", None) or ()), *(getattr(options, "extend_exclude", None) or ()))
        patterns = tuple(getattr(options, "filename", None) or ("*.py",))
        return cls(tuple(os.path.abspath(f) for f in (filenames or ["."])), tuple(exclude), patterns)

    def _excluded(self, path: str) -> bool:
        name = os.path.basename(path)
        return any(fnmatch.fnmatch(name, p) or fnmatch.fnmatch(path, p) for p in self.exclude)

    def __contains__(self, path: object) -> bool:
        if not isinstance(path, (str, Path)):
            return False
        path = os.path.abspath(path)
        for target in self.targets:
            if path == target:
                return not self._excluded(path)
            if path.startswith(target.rstrip(os.sep) + os.sep) and self._under(target, path):
                return True
        return False

    def _under(self, target: str, path: str) -> bool:
        if self._excluded(target) or not any(fnmatch.fnmatch(path, p) for p in self.patterns):
            return False
        folder = os.path.dirname(path)
        while len(folder) > len(target):
            if self._excluded(folder):
                return False
            folder = os.path.dirname(folder)
        return not self._excluded(path)
