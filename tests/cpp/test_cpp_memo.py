"""The C++ partner ends kept between runs: an exact round trip, reused while no C++ source or
package folder changes, read again when one does, and the findings always those of a cold run."""
from __future__ import annotations

import json
import shutil
import time
from pathlib import Path

import pytest

from flake8_rosgraph import cache
from flake8_rosgraph.cpp import memo, to_graph
from flake8_rosgraph.options import Settings

MIXED = Path(__file__).resolve().parent.parent / "eval" / "cpp_mixed_workspace"


def test_the_ends_survive_the_round_trip_exactly() -> None:
    nodes, diagnostics = to_graph.cpp_graph(MIXED)
    assert nodes, "the mixed workspace has C++ nodes"
    assert memo.from_obj(json.loads(json.dumps(memo.to_obj(nodes, diagnostics)))) == (nodes, diagnostics)


@pytest.mark.parametrize("damage", ["{", "[]", '{"format": 1}', '{"format": 1, "nodes": [{"x": 1}], '
                                                                 '"diagnostics": []}'])
def test_what_is_not_a_memo_is_refused(damage: str) -> None:
    with pytest.raises((ValueError, KeyError, TypeError)):
        memo.from_obj(json.loads(damage) if damage != "{" else None)


def test_a_python_edit_reuses_the_ends_and_a_cpp_edit_reads_them_again(tmp_path: Path,
                                                                          monkeypatch: pytest.MonkeyPatch) -> None:
    root = tmp_path / "ws"
    shutil.copytree(MIXED, root)
    time.sleep(cache.RACY_SECONDS + 0.2)
    reads: list[Path] = []
    real = to_graph.cpp_graph
    monkeypatch.setattr(to_graph, "cpp_graph", lambda where: reads.append(where) or real(where))
    settings = Settings()
    first = cache.load_or_build(root, settings)
    python_file = next(p for p in sorted(root.rglob("*.py")) if "setup" not in p.name)
    python_file.write_text(python_file.read_text() + "\n# edited\n")
    cache.start_run()
    assert cache.load_or_build(root, settings).findings == first.findings
    assert len(reads) == 1  # the C++ tree did not change: its ends came from the cache
    cpp_file = next(iter(sorted(root.rglob("*.cpp"))))
    cpp_file.write_text(cpp_file.read_text() + "\n// edited\n")
    cache.start_run()
    again = cache.load_or_build(root, settings)
    assert len(reads) == 2
    assert again == cache.build_report(root, settings)  # as a run without any cache
    # A package's own interface decides what its C++ ``msg::Name`` is: a new one reads them again.
    package = next(iter(sorted(root.rglob("package.xml")))).parent
    (package / "msg").mkdir(exist_ok=True)
    (package / "msg" / "Heartbeat.msg").write_text("uint32 sequence\n")
    before = len(reads)
    cache.start_run()
    cache.load_or_build(root, settings)
    assert len(reads) == before + 1
