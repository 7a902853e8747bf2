"""End-to-end eval files, flake8-bugbear style: extract the graph of each workspace under tests/eval, run the
rules, and compare (code, path, line) with the codes written in comments on the reported lines.

A comment that *starts* with codes declares them (``...  # ROS001`` or ``# ROS004, ROS005``); prose
comments that merely mention a code do not. A case may hold ``rosgraph-eval.toml`` with ``select``
(codes or prefixes; default: the default-enabled rules) and ``external_names``.
Skipped only while ``flake8_rosgraph.analysis`` (the extractor) does not exist.
"""
from __future__ import annotations

import importlib
import importlib.util
import re
import tokenize
from pathlib import Path

import pytest

from flake8_rosgraph.rules import RuleConfig, run_rules

try:
    import tomllib
except ImportError:  # Python < 3.11
    import tomli as tomllib

EVAL_DIR = Path(__file__).resolve().parents[1] / "eval"
CASES = sorted(p for p in EVAL_DIR.iterdir() if p.is_dir()) if EVAL_DIR.is_dir() else []
CONFIG_FILE = "rosgraph-eval.toml"
_DECLARATION = re.compile(r"#\s*(ROS\d{3}(?:\s*,?\s*ROS\d{3})*)\b")
_CODE = re.compile(r"ROS\d{3}")


def expected_findings(case: Path) -> list[tuple[str, str, int]]:
    """The (code, root-relative path, line) triples declared in the comments of a case's Python files."""
    expected = set()
    for path in sorted(case.rglob("*.py")):
        with tokenize.open(path) as source:
            for token in tokenize.generate_tokens(source.readline):
                match = _DECLARATION.match(token.string) if token.type == tokenize.COMMENT else None
                if match:
                    rel = path.relative_to(case).as_posix()
                    expected.update((code, rel, token.start[0]) for code in _CODE.findall(match.group(1)))
    return sorted(expected)


def test_declarations_are_parsed_from_comments_only(tmp_path):
    (tmp_path / "m.py").write_text(
        "x = '# ROS001'  # ROS002, ROS003\n"
        "# a comment about ROS004 declares nothing\n"
        "y = 1  # ROS005 -- with an explanation\n")
    assert expected_findings(tmp_path) == [("ROS002", "m.py", 1), ("ROS003", "m.py", 1), ("ROS005", "m.py", 3)]


def _build_graph():
    if importlib.util.find_spec("flake8_rosgraph.analysis") is None:
        pytest.skip("the extractor flake8_rosgraph.analysis is not there yet")
    return importlib.import_module("flake8_rosgraph.analysis").build_graph


@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
def test_eval_case(case: Path):
    build_graph = _build_graph()
    settings = {}
    if (case / CONFIG_FILE).exists():
        settings = tomllib.loads((case / CONFIG_FILE).read_text(encoding="utf-8"))
    config = RuleConfig(external_names=frozenset(settings.get("external_names", ())))
    graph = build_graph(case)
    from flake8_rosgraph.launch.api import judged_graph

    # judged as launched, as flake8 and ``check`` judge it (cache.build_report)
    findings = run_rules(judged_graph(graph, graph.systems), config, settings.get("select"))
    actual = sorted({(f.code, f.location.path, f.location.line) for f in findings})
    details = "\n".join(f"  {f.code} {f.location.short()} {f.message}" for f in findings)
    diagnostics = "\n".join(f"  {d.path}:{d.line} {d.message}" for d in graph.diagnostics)
    assert actual == expected_findings(case), f"findings:\n{details}\nanalysis diagnostics:\n{diagnostics}"
