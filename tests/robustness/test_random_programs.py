"""Random valid Python never makes ``build_graph`` fail, hang or answer differently twice.

Two sources: ``hypothesmith`` (arbitrary programs from Python's grammar, with an
``import rclpy`` added so that the analyser starts from them) and our own
generator of rclpy-flavoured programs (:mod:`.program_generator`), which reach
the ROS models far more often. Each program is written to a fresh temporary
workspace and analysed in-process under an alarm-based hang guard.
"""
from __future__ import annotations

import ast
import contextlib
import os
import signal
import tempfile
import warnings
from pathlib import Path
from typing import Iterator

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from flake8_rosgraph.analysis import build_graph
from flake8_rosgraph.graph.dot import to_dot
from flake8_rosgraph.graph.json_out import to_json

from .harness import HANG_GUARD_S
from .program_generator import programs

RANDOM = settings(max_examples=60, deadline=None, database=None, derandomize=False,
                  suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                         HealthCheck.filter_too_much])


class Hang(BaseException):
    """Raised by the alarm; a BaseException so that ``build_graph``'s own safety net cannot swallow it."""


@contextlib.contextmanager
def hang_guard(seconds: float) -> Iterator[None]:
    if not hasattr(signal, "setitimer"):
        yield
        return

    def alarm(signum: int, frame: object) -> None:
        raise Hang(f"build_graph did not finish within {seconds} s")

    previous = signal.signal(signal.SIGALRM, alarm)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


def analyse_source(files: dict[str, str]) -> tuple[str, str]:
    """JSON and DOT of a temporary workspace holding ``files``; checks the run had no internal error."""
    with tempfile.TemporaryDirectory(prefix="rosgraph-random-") as folder:
        root = Path(folder)
        for rel, text in files.items():
            (root / rel).write_text(text, encoding="utf-8")
        with hang_guard(HANG_GUARD_S):
            graph = build_graph(root)
        internal = [d for d in graph.diagnostics if "internal error" in d.message]
        assert not internal, f"internal error on a valid program: {internal}"
        first = to_json(graph), to_dot(graph)
        with hang_guard(HANG_GUARD_S):
            again = build_graph(root)
        assert (to_json(again), to_dot(again)) == first, "two runs on the same program differ"
    return first


def _parses(source: str) -> bool:
    """Whether this Python parses ``source`` and it can be stored as UTF-8 (no lone surrogates)."""
    try:
        source.encode("utf-8")
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            ast.parse(source)
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return False
    return True


@RANDOM
@given(programs())
def test_rclpy_flavoured_programs(source: str) -> None:
    assert _parses(source), f"the generator produced invalid Python:\n{source}"
    analyse_source({"generated.py": source})


@settings(RANDOM, max_examples=30)
@given(programs(), programs())
def test_programs_importing_each_other(first: str, second: str) -> None:
    analyse_source({"first.py": first + "\nfrom second import *\nimport second\n",
                    "second.py": second + "\nfrom first import Gen0\nimport first\n"})


@pytest.fixture(scope="module")
def grammar_programs() -> st.SearchStrategy[str]:
    hypothesmith = pytest.importorskip("hypothesmith", reason="hypothesmith is not installed (test extra)")
    return hypothesmith.from_grammar()


@settings(RANDOM, max_examples=40)
@given(data=st.data())
def test_programs_from_the_python_grammar(grammar_programs: st.SearchStrategy[str], data: st.DataObject) -> None:
    source = data.draw(grammar_programs)
    module = source + ("" if source.endswith("\n") or not source else "\n") + "import rclpy\n"
    assume(_parses(module))
    analyse_source({"grammar.py": module})


@pytest.mark.skipif(os.name != "posix", reason="the hang guard needs SIGALRM")
def test_hang_guard_stops_a_hang() -> None:
    """The guard itself must work, or the properties above could hang instead of failing."""
    with pytest.raises(Hang):
        with hang_guard(0.2):
            while True:
                pass
