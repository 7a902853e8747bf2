"""The analysed code is never imported or run, by any entry point.

Every fixture file would, if imported, write a marker file and stop the
process. Some are named after modules the tool itself imports after start-up
(``argparse``, ``json``, ``tokenize`` …), so that running the tool from inside
the workspace — where ``python -m`` puts the current folder first on
``sys.path`` — would execute them if the tool let that folder shadow its own
imports. Afterwards no marker may exist, the analysis must still have read the
files (their nodes are in the graph), and no workspace module may be loaded.
"""
from __future__ import annotations

import sys
from pathlib import Path

import pytest

from flake8_rosgraph.analysis import build_graph
from flake8_rosgraph.graph.json_out import to_json_obj

from .harness import (assert_clean_exit, clean_env, entity_keys, flake8_cli, parse_graph, plugin_available,
                      run)
from .hostile_inputs import GOOD_ENTITIES, GOOD_FILES, write_files

#: Imported by the tool (or its dependencies) after the interpreter started, never by Python's start-up.
SHADOWED_MODULES = ("argparse", "json", "tokenize", "ast", "dataclasses", "heapq", "traceback", "string",
                    "difflib", "networkx", "tomli", "tomllib")

TRAP = """\
import os
os.makedirs({markers!r}, exist_ok=True)
open(os.path.join({markers!r}, {name!r} + '.ran'), 'w').write('imported')

import rclpy
from std_msgs.msg import String
node = rclpy.create_node({node!r})
node.create_publisher(String, {topic!r}, 10)
os._exit(17)
raise SystemExit(17)
"""


def trap(markers: Path, name: str) -> bytes:
    node = "trap_" + name.replace(".", "_").replace("/", "_")
    return TRAP.format(markers=str(markers), name=name, node=node, topic=node + "_topic").encode()


@pytest.fixture
def markers(tmp_path: Path) -> Path:
    return tmp_path / "markers"


@pytest.fixture
def workspace(tmp_path: Path, markers: Path) -> Path:
    root = tmp_path / "ws"
    files = {k: v.encode() for k, v in GOOD_FILES.items()}
    files.update({f"{name}.py": trap(markers, name) for name in SHADOWED_MODULES})
    files.update({
        "evil.py": trap(markers, "evil"),
        "setup.py": trap(markers, "setup"),
        "conftest.py": trap(markers, "conftest"),
        "sitecustomize.py": trap(markers, "sitecustomize"),
        "usercustomize.py": trap(markers, "usercustomize"),
        "trappkg/__init__.py": trap(markers, "trappkg"),
        "trappkg/__main__.py": trap(markers, "trappkg.__main__"),
        "trappkg/launch/demo.launch.py": trap(markers, "demo.launch"),
    })
    write_files(root, files)
    return root


def assert_nothing_ran(markers: Path) -> None:
    ran = sorted(p.name for p in markers.glob("*.ran")) if markers.exists() else []
    assert not ran, f"analysed code was executed: {ran}"


def assert_traps_were_read(graph: dict) -> None:
    found = entity_keys(graph)
    assert GOOD_ENTITIES <= found
    fqns = {fqn for fqn, *_ in found}
    assert {"/trap_evil", "/trap_argparse", "/trap_trappkg"} <= fqns, sorted(fqns, key=str)


def test_graph_console_script_from_inside_the_workspace(workspace: Path, markers: Path) -> None:
    script = Path(sys.executable).with_name("flake8-rosgraph")
    if not script.exists():
        pytest.skip("the flake8-rosgraph console script is not installed next to this interpreter")
    done = run([str(script), "graph", ".", "--format", "json"], workspace)
    assert_nothing_ran(markers)
    assert_clean_exit(done)
    assert_traps_were_read(parse_graph(done))


def test_python_dash_m_from_inside_the_workspace(workspace: Path, markers: Path) -> None:
    """``python -m flake8_rosgraph graph .`` run in the workspace: the documented command, the riskiest place.

    ``PYTHONSAFEPATH`` is blanked so that a developer's setting cannot hide the problem.
    """
    done = run([sys.executable, "-m", "flake8_rosgraph", "graph", ".", "--format", "json"], workspace,
               clean_env(PYTHONSAFEPATH=""))
    assert_nothing_ran(markers)
    assert_clean_exit(done)
    assert_traps_were_read(parse_graph(done))


def test_check_command_from_inside_the_workspace(workspace: Path, markers: Path, tmp_path: Path) -> None:
    done = run([sys.executable, "-m", "flake8_rosgraph", "check", ".", "--root", ".",
                "--cache-dir", str(tmp_path / "cache")], workspace, clean_env(PYTHONSAFEPATH=""))
    assert_nothing_ran(markers)
    assert_clean_exit(done, allowed=(0, 1))


@pytest.mark.skipif(not plugin_available(), reason="flake8_rosgraph.plugin is not written yet (colleague's task)")
def test_flake8_plugin(workspace: Path, markers: Path) -> None:
    done = flake8_cli(workspace)
    assert_nothing_ran(markers)
    assert_clean_exit(done, allowed=(0, 1))


def test_build_graph_in_process(workspace: Path, markers: Path) -> None:
    before = set(sys.modules)
    graph = to_json_obj(build_graph(workspace))
    assert_nothing_ran(markers)
    assert_traps_were_read(graph)
    loaded = {name for name in set(sys.modules) - before
              if getattr(sys.modules[name], "__file__", None)
              and Path(sys.modules[name].__file__).resolve().is_relative_to(workspace.resolve())}
    assert not loaded, f"workspace modules were imported: {sorted(loaded)}"
