"""How cost grows with workspace size: a series over synthetic workspaces and a log-log fit.

The whole-workspace analysis is the part that could grow faster than the code
(the interpreter joins values across modules until a fixpoint), so the series
measures it at 1×, 2×, 4×, … copies of the same kind of code and fits
``time ≈ c · lines^k``. ``k`` near 1 is linear; the target is ``k ≤ 1.1``.
Start-up costs are included (they are part of what users wait for), which
pulls ``k`` slightly below the true exponent of the analysis at small sizes.
"""
from __future__ import annotations

import math
import shutil
import statistics
from dataclasses import dataclass
from pathlib import Path
from typing import Sequence

import synth
from measure import Summary
from steps import Corpus, WorkspaceBench, run_steps

#: Scale factors of the series (number of synthetic fleets).
DEFAULT_SCALES = (1, 2, 4, 8, 16)


@dataclass(frozen=True)
class GrowthPoint:
    scale: int
    files: int
    lines: int
    summaries: dict[str, Summary]


def measure_growth(work_dir: Path, scales: Sequence[int], runs: int, with_plugin: bool) -> list[GrowthPoint]:
    """Generate each scale's workspace in ``work_dir``, measure it, delete it again."""
    points = []
    for scale in scales:
        root = synth.write_workspace(work_dir / f"scale-{scale}", scale)
        corpus = Corpus.scan(root)
        bench = WorkspaceBench(corpus)
        steps = [bench.ast_parse(), bench.flake8_without()]
        if with_plugin:
            steps.append(bench.flake8_cold())
        steps.append(bench.graph())
        points.append(GrowthPoint(scale, len(corpus.files), corpus.lines, run_steps(steps, runs)))
        shutil.rmtree(root)
    return points


def loglog_exponent(sizes: Sequence[float], times: Sequence[float]) -> float | None:
    """Least-squares slope of log(time) over log(size); ``None`` with fewer than two usable points."""
    pairs = [(math.log(s), math.log(t)) for s, t in zip(sizes, times) if s > 0 and t > 0]
    if len(pairs) < 2 or len({x for x, _ in pairs}) < 2:
        return None
    xs, ys = zip(*pairs)
    return statistics.linear_regression(xs, ys).slope


def series(points: Sequence[GrowthPoint], key: str, cpu: bool = False) -> list[float]:
    """Median wall (or CPU) times of step ``key`` along the series."""
    return [p.summaries[key].cpu_s if cpu else p.summaries[key].wall_s for p in points]


def plugin_overhead(points: Sequence[GrowthPoint], cpu: bool = False) -> list[float]:
    """What the plugin adds to a cold flake8 run, along the series."""
    return [c - w for c, w in zip(series(points, "cold", cpu), series(points, "flake8", cpu))]
