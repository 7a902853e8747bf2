"""Which nodes are test fixtures, and which other nodes a fixture can talk to.

A package's tests start nodes of their own (a fake driver publishing what the
node under test subscribes, a probe subscribing to its output), usually in
``test/`` and often under the production names. Such a node runs only in the
test process or the test's launch file, never next to the production system,
so matching it against production nodes makes wiring look right that is
broken (a test publisher "connects" a production typo) and broken that is
right (a fixture's probe looks like a dangling end of the product).

A node is a *fixture* when its creation site is in a test file (under a
``test``/``tests`` folder, or a ``test_*.py``/``*_test.py``/``conftest.py``
module), or when a launch file in such a place starts it (a production node
launched by a launch test is part of that test). A fixture's *scope* is the
path prefix of the package it tests: the folder that holds the test folder
(``pkg/test/test_x.py`` -> ``pkg/``) or the test module's folder. Fixtures see
the fixtures of their scope and the production nodes under it; production
nodes see production nodes only.

A test module under a test folder (``pkg/test/test_x.py``) is one *test run*:
pytest runs its tests on their own, each creating its nodes and destroying them
again, so the nodes two such modules create never run together. Their ends only
meet the fixtures of no test run (helpers, nodes a launch test starts) and the
product, whatever names and types the two tests happen to share (``/bla`` as
``String`` in one, as ``Int32`` in the other).
"""
from __future__ import annotations

from functools import lru_cache
from pathlib import PurePosixPath

from ..graph.model import RosNode

#: Folder names whose contents are tests.
TEST_FOLDERS = frozenset({"test", "tests"})


def _is_test_module(basename: str) -> bool:
    stem = basename.split(".", 1)[0]
    # ``smoke.test.py``: a launch test named as CMake's ``add_launch_test`` runs it.
    launch_test = basename.endswith(".test.py")
    return stem.startswith("test_") or stem.endswith("_test") or stem == "conftest" or launch_test


@lru_cache(maxsize=4096)
def fixture_scope(path: str) -> str | None:
    """The scope prefix of a test file (``"pkg/"``, ``""`` at the root), or ``None`` for production code."""
    parts = PurePosixPath(path).parts
    for i, part in enumerate(parts[:-1]):
        if part in TEST_FOLDERS:
            return "".join(f"{p}/" for p in parts[:i])
    if parts and _is_test_module(parts[-1]):
        return "".join(f"{p}/" for p in parts[:-1])
    return None


def node_scope(node: RosNode) -> str | None:
    """The node's fixture scope, ``None`` for a production node (see the module docstring)."""
    scope = fixture_scope(node.location.path)
    if scope is None and node.launch is not None and isinstance(node.launch.get("file"), str):
        scope = fixture_scope(node.launch["file"])
    return scope


@lru_cache(maxsize=4096)
def _test_module(path: str) -> bool:
    parts = PurePosixPath(path).parts
    return bool(parts) and any(part in TEST_FOLDERS for part in parts[:-1]) \
        and _is_test_module(parts[-1]) and parts[-1].split(".", 1)[0] != "conftest"


def test_run(node: RosNode) -> str | None:
    """The test module a node is created in when no launch file starts it, ``None`` for
    any other node (see the module docstring)."""
    return node.location.path if node.launch is None and _test_module(node.location.path) else None


def sees(own_scope: str | None, other_scope: str | None, other_path: str) -> bool:
    """Whether an end in ``own_scope`` can be connected to one in ``other_scope`` created in ``other_path``."""
    if own_scope is None:
        return other_scope is None
    if other_scope is None:
        return other_path.startswith(own_scope)
    return other_scope == own_scope
