"""Plain-text tables of the measurements, and the speed targets with their verdicts.

The tables are Markdown pipe tables so they can be pasted into
``benchmarks/README.md`` as they are printed.
"""
from __future__ import annotations

import datetime
import os
import platform
from dataclasses import dataclass
from pathlib import Path
from typing import Sequence

from growth import GrowthPoint, loglog_exponent, plugin_overhead, series
from measure import Summary
from steps import Corpus

#: Peak memory allowed at about 100,000 lines.
MEMORY_LIMIT_MB = 300.0


@dataclass(frozen=True)
class Machine:
    """Where and under what load the numbers were taken."""

    system: str
    cpu: str
    cpus: int
    python: str
    flake8: str
    load_before: float
    load_after: float
    date: str = ""

    @classmethod
    def describe(cls, flake8_version: str, load_before: float) -> Machine:
        return cls(f"{platform.system()} {platform.machine()}", _cpu_model(), os.cpu_count() or 0,
                   platform.python_version(), " ".join(flake8_version.split()),
                   load_before, os.getloadavg()[0],
                   datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"))

    def line(self) -> str:
        return (f"{self.date}; machine: {self.system}, {self.cpus} CPUs ({self.cpu}); Python {self.python}; "
                f"flake8 {self.flake8}; 1-min load average {self.load_before:.2f} before, "
                f"{self.load_after:.2f} after")


def _cpu_model() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text(encoding="utf-8").splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


@dataclass(frozen=True)
class Target:
    """One requirement: ``value`` must be ≤ ``limit``.

    ``value`` is from wall-clock times, as users experience them; ``cpu_value``,
    where it applies, is the same figure from CPU times, which other work on the
    machine disturbs much less (all measured commands but the --jobs=auto ones are
    single-threaded).
    """

    name: str
    value: float | None
    limit: float
    unit: str
    cpu_value: float | None = None

    @property
    def verdict(self) -> str:
        if self.value is None:
            return "not measured"
        return "met" if self.value <= self.limit else "MISSED"

    def row(self) -> str:
        return (f"| {self.name} | {_fmt(self.value, '.2f')}{self.unit} | {_fmt(self.cpu_value, '.2f')}"
                f"{self.unit if self.cpu_value is not None else ''} | ≤ {self.limit:.2f}{self.unit} "
                f"| {self.verdict} |")


def _ratio(summaries: dict[str, Summary], key: str, base: str, cpu: bool = False) -> float | None:
    if key not in summaries or base not in summaries:
        return None
    if cpu:
        return summaries[key].cpu_s / summaries[base].cpu_s if summaries[base].cpu_s > 0 else None
    return summaries[key].wall_s / summaries[base].wall_s if summaries[base].wall_s > 0 else None


def _fmt(value: float | None, pattern: str) -> str:
    return "–" if value is None else format(value, pattern)


def workspace_table(corpus: Corpus, source: str, runs: int, summaries: dict[str, Summary],
                    results: dict[str, str]) -> str:
    """One row per step: medians, spread, throughput, memory, ratios to the floor and to flake8."""
    rows = [
        f"workspace: {source} — {len(corpus.files)} files, {corpus.lines:,} lines; "
        f"median of {runs} run(s)",
        "",
        "| step | wall s | min–max s | CPU s | lines/s | peak MB | × ast.parse | × flake8 | result |",
        "|---|---:|---:|---:|---:|---:|---:|---:|---|",
    ]
    for key, summary in summaries.items():
        per_line = key != "startup" and not key.startswith("precommit")  # those read one file
        rows.append(
            f"| {summary.label} | {summary.wall_s:.3f} | {summary.wall_min_s:.3f}–{summary.wall_max_s:.3f} "
            f"| {summary.cpu_s:.3f} "
            f"| {_fmt(corpus.lines / summary.wall_s if per_line and summary.wall_s else None, ',.0f')} "
            f"| {_fmt(summary.peak_mb, '.1f')} "
            f"| {_fmt(_ratio(summaries, key, 'ast'), '.1f')} "
            f"| {_fmt(_ratio(summaries, key, 'flake8'), '.2f')} | {results.get(key, '')} |")
    return "\n".join(rows)


def workspace_targets(summaries: dict[str, Summary]) -> list[Target]:
    """The per-workspace targets (ratios of the same files in the same run).

    The "graph command well under one second" target is about ros2/demos only, so
    it is read off that workspace's table rather than judged on every workspace.
    """
    def ratio_target(name: str, key: str, base: str, limit: float) -> Target:
        return Target(name, _ratio(summaries, key, base), limit, "×", _ratio(summaries, key, base, cpu=True))

    return [
        ratio_target("flake8 + plugin cold ÷ flake8 without", "cold", "flake8", 1.20),
        ratio_target("flake8 + plugin warm ÷ flake8 without", "warm", "flake8", 1.02),
        ratio_target("one file changed ÷ warm (≈ warm)", "changed", "warm", 1.05),
        ratio_target("topic renamed in a leaf module ÷ flake8 without", "renamed", "flake8", 1.10),
        Target("pre-commit on the edited file (wall s)",
               summaries["precommit"].wall_s if "precommit" in summaries else None, 1.0, " s",
               summaries["precommit"].cpu_s if "precommit" in summaries else None),
        # --jobs=auto: the workers run side by side, so only the wall ratio means anything.
        Target("--jobs=auto cold ÷ --jobs=auto without (wall)", _ratio(summaries, "cold-auto", "flake8-auto"),
               1.20, "×", None),
        ratio_target("graph command ÷ ros2inspector graph (peer)", "graph", "peer-graph", 1.00),
        ratio_target("graph command --jobs 1 ÷ ros2inspector graph (peer)", "graph-1", "peer-graph", 1.00),
    ]


def targets_table(targets: Sequence[Target]) -> str:
    return "\n".join(["| target | wall | CPU | limit | verdict |", "|---|---:|---:|---:|---|",
                      *(t.row() for t in targets)])


def growth_table(points: Sequence[GrowthPoint], runs: int) -> str:
    """One row per scale: size, median wall times and peak memory of each step."""
    keys = list(points[0].summaries)
    labels = {"ast": "ast.parse", "flake8": "flake8 w/o", "cold": "flake8 + plugin cold", "graph": "graph"}
    head = ["scale", "files", "lines"] + [f"{labels[k]} s" for k in keys] + [
        f"peak MB {labels[k]}" for k in keys if k != "ast"]
    rows = [f"growth series: synthetic workspace (benchmarks/synth.py); median of {runs} run(s), "
            "wall s (CPU s)", "",
            "| " + " | ".join(head) + " |", "|" + "---:|" * len(head)]
    for p in points:
        cells = [f"{p.scale}×", str(p.files), f"{p.lines:,}"]
        cells += [f"{p.summaries[k].wall_s:.3f} ({p.summaries[k].cpu_s:.3f})" for k in keys]
        cells += [_fmt(p.summaries[k].peak_mb, ".1f") for k in keys if k != "ast"]
        rows.append("| " + " | ".join(cells) + " |")
    return "\n".join(rows)


def growth_exponents(points: Sequence[GrowthPoint], cpu: bool = False) -> dict[str, float | None]:
    """Fitted exponent ``k`` of ``time ≈ c · lines^k`` for each step, plus the plugin's own share."""
    sizes = [p.lines for p in points]
    exponents = {key: loglog_exponent(sizes, series(points, key, cpu)) for key in points[0].summaries}
    if "cold" in points[0].summaries:
        exponents["plugin"] = loglog_exponent(sizes, plugin_overhead(points, cpu))
    return exponents


def growth_targets(points: Sequence[GrowthPoint]) -> list[Target]:
    wall, cpu = growth_exponents(points), growth_exponents(points, cpu=True)
    largest = points[-1]
    targets = [
        Target(f"growth exponent, {label}", wall.get(key), 1.10, "", cpu.get(key))
        for key, label in (("graph", "graph command"), ("cold", "flake8 + plugin cold"),
                           ("plugin", "plugin share (cold − without)"))
    ]
    for key, label in (("cold", "flake8 + plugin cold"), ("graph", "graph command")):
        peak = largest.summaries[key].peak_mb if key in largest.summaries else None
        name = f"peak memory at {largest.lines:,} lines, {label}"
        targets.append(Target(name, peak, MEMORY_LIMIT_MB, " MB"))
    return targets


def exponents_line(points: Sequence[GrowthPoint]) -> str:
    names = {"ast": "ast.parse", "flake8": "flake8 w/o", "cold": "flake8 + plugin cold",
             "graph": "graph", "plugin": "plugin share"}
    wall, cpu = growth_exponents(points), growth_exponents(points, cpu=True)
    parts = [f"{names[k]} k={_fmt(v, '.2f')} (CPU {_fmt(cpu[k], '.2f')})" for k, v in wall.items()]
    return "log-log fit, time ≈ c·lines^k: " + ", ".join(parts)


#: The block of ``benchmarks/README.md`` that ``run.py --readme`` rewrites.
README_BEGIN = "<!-- run.py --readme: begin -->"
README_END = "<!-- run.py --readme: end -->"


def with_readme_block(readme: str, printed: str, command: str) -> str:
    """``readme`` with the text between :data:`README_BEGIN` and :data:`README_END` replaced by
    ``printed`` (what the run printed, machine and date first) and the command that printed it."""
    start, end = readme.find(README_BEGIN), readme.find(README_END)
    if start < 0 or end < start:
        raise ValueError(f"no {README_BEGIN} … {README_END} block")
    block = f"{README_BEGIN}\nPrinted by `{command}`:\n\n```\n{printed.rstrip()}\n```\n"
    return readme[:start] + block + readme[end:]
