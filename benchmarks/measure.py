"""Timing one command (wall clock, CPU time, peak memory) and summarising repeated runs.

Each command runs under :mod:`rusage_exec`, which measures exactly that command
with ``os.wait4`` (see there why it is a separate small process).
``resource.getrusage(RUSAGE_CHILDREN)`` would not do: its ``ru_maxrss`` is the
largest child of the whole benchmark so far, not the one just run. Unix only.
"""
from __future__ import annotations

import statistics
import subprocess
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path
from typing import Mapping, Sequence

RUSAGE_EXEC = Path(__file__).resolve().parent / "rusage_exec.py"


class CommandFailed(RuntimeError):
    """A measured command exited with a status that means it did not do its job."""


@dataclass(frozen=True)
class Sample:
    """One measured run. ``peak_mb`` is ``None`` for in-process steps (no separate process to measure)."""

    wall_s: float
    cpu_s: float
    peak_mb: float | None
    stdout: str


def _maxrss_mb(maxrss: int) -> float:
    """``ru_maxrss`` is in KiB on Linux and in bytes on macOS."""
    return maxrss / (1024 * 1024) if sys.platform == "darwin" else maxrss / 1024


def run_command(argv: Sequence[str], cwd: Path, env: Mapping[str, str],
                ok_status: frozenset[int] = frozenset({0})) -> Sample:
    """Run ``argv`` to completion and measure it; :class:`CommandFailed` on an unexpected exit status."""
    with tempfile.TemporaryDirectory(prefix="rosgraph-bench-run-") as tmp:
        usage_file = Path(tmp, "usage")
        done = subprocess.run([sys.executable, "-S", str(RUSAGE_EXEC), str(usage_file), "--", *argv],
                              cwd=cwd, env=dict(env), stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                              check=False)
        if done.returncode not in ok_status:
            tail = done.stderr.decode("utf-8", "replace")[-2000:]
            raise CommandFailed(f"{' '.join(argv)} exited with {done.returncode}:\n{tail}")
        wall, cpu, maxrss = usage_file.read_text(encoding="ascii").split()
    return Sample(float(wall), float(cpu), _maxrss_mb(int(maxrss)), done.stdout.decode("utf-8", "replace"))


@dataclass(frozen=True)
class Summary:
    """The repeated runs of one step, reduced to what the tables show."""

    label: str
    samples: tuple[Sample, ...]

    @property
    def wall_s(self) -> float:
        return statistics.median(s.wall_s for s in self.samples)

    @property
    def wall_min_s(self) -> float:
        return min(s.wall_s for s in self.samples)

    @property
    def wall_max_s(self) -> float:
        return max(s.wall_s for s in self.samples)

    @property
    def cpu_s(self) -> float:
        return statistics.median(s.cpu_s for s in self.samples)

    @property
    def peak_mb(self) -> float | None:
        peaks = [s.peak_mb for s in self.samples if s.peak_mb is not None]
        return max(peaks) if peaks else None
