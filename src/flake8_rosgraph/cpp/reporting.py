"""C++ ends are partners only: every finding is located at a Python end.

The tool lints Python. The C++ front end reads rclcpp code shallowly (one
file's constants, no launch binding, no interprocedural values), and flake8
only checks ``.py`` files, so a finding located in a ``.cpp`` file would be
unfixable noise in one front end and missing in the other. Instead, after the
rules ran:

* a finding at a C++ location whose related locations include a Python end
  moves to the first Python end, prefixed with ``C++ end <file:line>:`` and
  with the C++ site added as related — a C++ publisher ``/chater`` near a
  Python subscription ``/chatter`` is reported at the subscription;
* unless a finding of the same code at that Python end already names the C++
  site (ROS003 at the subscription says "did you mean '/chater' (published at
  src/talker.cpp:12)": the moved ROS001 would repeat it);
* a finding with no Python end at all (two C++ nodes disagree) is dropped:
  that is a C++ problem, for C++ tools.
"""
from __future__ import annotations

from pathlib import PurePosixPath
from typing import Iterable

from ..findings import Finding
from ..graph.model import Location
from . import CPP_SUFFIXES


def is_cpp(location: Location) -> bool:
    return PurePosixPath(location.path).suffix in CPP_SUFFIXES


def at_python_ends(findings: Iterable[Finding]) -> list[Finding]:
    """``findings`` with every C++-located one moved to its Python end or dropped (see the module docstring)."""
    kept: list[Finding] = []
    moved: list[Finding] = []
    for finding in findings:
        (moved if is_cpp(finding.location) else kept).append(finding)
    named = {(f.location, f.code, loc) for f in kept for loc, _ in f.related}
    for finding in sorted(moved):
        python_ends = sorted(loc for loc, _ in finding.related if not is_cpp(loc))
        if not python_ends:
            continue
        target = python_ends[0]
        if (target, finding.code, finding.location) in named or \
                any((target, code, finding.location) in named for code in _SAME_PROBLEM.get(finding.code, ())):
            continue
        related = ((finding.location, "C++ end"),) + tuple(r for r in finding.related if r[0] != target)
        message = f"C++ end {finding.location.short()}: {finding.message}"
        kept.append(Finding(target, finding.code, message, related))
        named.add((target, finding.code, finding.location))
    return sorted(set(kept))


#: Codes that report one broken connection from its two sides (a dangling publisher and the
#: dangling subscription it was meant for): one of them at the Python end is enough.
_SAME_PROBLEM: dict[str, tuple[str, ...]] = {
    "ROS001": ("ROS003",), "ROS003": ("ROS001",),
}
