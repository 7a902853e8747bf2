"""Speed benchmark of flake8-rosgraph: ``python benchmarks/run.py [DIR] [--runs N] [--growth] [--json OUT]``.

Measures, on one workspace and in one run (so the ratios compare the same files
under the same machine load): the ``ast.parse`` floor, pyflakes, flake8 ``-j1``
without and with the plugin (cold, warm, one file changed) and the standalone
``graph`` command; prints Markdown tables of medians and the targets' verdicts.
``--growth`` adds the growth series on synthetic workspaces (log-log exponent,
peak memory at about 100,000 lines).

DIR is copied to a temporary directory first: the cold/warm steps create the
plugin's cache in the workspace and the one-file-changed step edits a file, and
neither may touch the original. Run it with the interpreter of a virtual
environment where flake8-rosgraph is installed; see benchmarks/README.md.
"""
from __future__ import annotations

import argparse
import json
import os
import shutil
import sys
import tempfile
import time
from dataclasses import asdict
from pathlib import Path

from flake8_rosgraph.cache import CACHE_DIR_NAME, RACY_SECONDS

import growth
import report
from measure import CommandFailed, Summary
from steps import PLUGIN_DIST, Corpus, LeafEdit, Step, WorkspaceBench, run_steps

REPO = Path(__file__).resolve().parent.parent


def plugin_state(bench: WorkspaceBench) -> tuple[str, bool]:
    """flake8's version line, and whether the plugin loads; exits if hiding it does not work."""
    without = bench.flake8_version(with_plugin=False)
    if PLUGIN_DIST in without:
        raise SystemExit(f"run.py: could not hide {PLUGIN_DIST} from flake8: {without.strip()}")
    try:
        with_plugin = bench.flake8_version(with_plugin=True)
    except CommandFailed as exc:  # the plugin is installed but cannot be loaded
        print(f"note: flake8 fails with the plugin, measuring without it: {exc}", file=sys.stderr)
        return without, False
    return with_plugin, PLUGIN_DIST in with_plugin


def workspace_steps(bench: WorkspaceBench, with_plugin: bool, peer: str | None) -> list[Step]:
    steps = [bench.startup(), bench.ast_parse(), bench.pyflakes(), bench.flake8_without()]
    if with_plugin:
        steps += [bench.flake8_cold(), bench.flake8_warm(), bench.flake8_one_changed()]
        edit = LeafEdit.find(bench.root)
        if edit is not None:  # a workspace without a topic literal in a leaf module has no such rows
            steps += [bench.flake8_topic_renamed(edit), bench.precommit(edit, False),
                      bench.precommit(edit, True)]
    steps.append(bench.flake8_without_auto())
    if with_plugin:
        steps.append(bench.flake8_cold_auto())
    return steps + [bench.graph(), bench.graph(jobs=1)] + ([bench.peer_graph(peer)] if peer else [])


def summary_obj(summary: Summary, result: str) -> dict[str, object]:
    return {"label": summary.label, "wall_s": summary.wall_s, "wall_min_s": summary.wall_min_s,
            "wall_max_s": summary.wall_max_s, "cpu_s": summary.cpu_s, "peak_mb": summary.peak_mb,
            "result": result, "wall_samples_s": [s.wall_s for s in summary.samples]}


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("dir", nargs="?", type=Path, default=REPO / "examples",
                        help="workspace to measure (default: the repository's examples/)")
    parser.add_argument("--runs", type=int, default=5, help="repetitions per step (default 5)")
    parser.add_argument("--growth", action="store_true", help="also run the synthetic growth series")
    parser.add_argument("--scales", default=",".join(map(str, growth.DEFAULT_SCALES)),
                        help="growth series scale factors (default %(default)s)")
    parser.add_argument("--json", type=Path, metavar="OUT", help="also write all measurements as JSON")
    parser.add_argument("--peer", default=os.environ.get("ROS2INSPECTOR") or shutil.which("ros2inspector"),
                        help="the ros2inspector executable that `graph` is compared with (default: "
                             "$ROS2INSPECTOR, else ros2inspector on PATH; without it that row is missing)")
    parser.add_argument("--readme", action="store_true",
                        help="also put the printed tables into benchmarks/README.md (its latest-results block)")
    args = parser.parse_args(argv)
    if not args.dir.is_dir():
        parser.error(f"not a directory: {args.dir}")
    if args.runs < 1:
        parser.error("--runs must be at least 1")
    scales = [int(s) for s in args.scales.split(",") if s.strip()]

    load_before = os.getloadavg()[0]
    with tempfile.TemporaryDirectory(prefix="rosgraph-bench-") as tmp:
        work = Path(tmp)
        copy = shutil.copytree(args.dir, work / "ws", symlinks=True,
                               ignore=shutil.ignore_patterns(".git", CACHE_DIR_NAME))
        # Files written a moment ago are hashed on every run (the cache's racy window); a
        # checked-out workspace is older than that, so let the copy settle first.
        time.sleep(RACY_SECONDS + 0.5)
        corpus = Corpus.scan(Path(copy))
        bench = WorkspaceBench(corpus)
        bench.compile_measured()
        version, with_plugin = plugin_state(bench)
        steps = workspace_steps(bench, with_plugin, args.peer)
        summaries = run_steps(steps, args.runs)
        results = {step.key: step.describe(summaries[step.key].samples[-1].stdout) for step in steps}
        points = growth.measure_growth(work, scales, args.runs, with_plugin) if args.growth else []
    machine = report.Machine.describe(version, load_before)

    targets = report.workspace_targets(summaries)
    out = [machine.line()]
    if not with_plugin:
        out.append(f"note: {PLUGIN_DIST} is not loadable by flake8; its rows are missing")
    if not args.peer:
        out.append("note: ros2inspector is not installed (pip install ros2inspector==0.1.5, or --peer PATH); "
                   "the graph ÷ peer row is missing")
    out += ["", report.workspace_table(corpus, str(args.dir), args.runs, summaries, results), ""]
    if points:
        out += [report.growth_table(points, args.runs), "", report.exponents_line(points), ""]
        targets += report.growth_targets(points)
    out.append(report.targets_table(targets))
    printed = "\n".join(out)
    print(printed)
    if args.readme:
        readme = Path(__file__).resolve().parent / "README.md"
        command = " ".join(["benchmarks/run.py", *(argv if argv is not None else sys.argv[1:])])
        readme.write_text(report.with_readme_block(readme.read_text(encoding="utf-8"), printed, command),
                          encoding="utf-8")

    if args.json:
        data = {
            "machine": asdict(machine),
            "workspace": {"source": str(args.dir), "files": len(corpus.files), "lines": corpus.lines,
                          "runs": args.runs,
                          "steps": {k: summary_obj(s, results[k]) for k, s in summaries.items()}},
            "growth": [{"scale": p.scale, "files": p.files, "lines": p.lines,
                        "steps": {k: summary_obj(s, "") for k, s in p.summaries.items()}}
                       for p in points],
            "growth_exponents": {"wall": report.growth_exponents(points),
                                 "cpu": report.growth_exponents(points, cpu=True)} if points else {},
            "targets": [{**asdict(t), "verdict": t.verdict} for t in targets],
        }
        args.json.write_text(json.dumps(data, indent=1) + "\n", encoding="utf-8")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
