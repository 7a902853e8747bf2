"""Same workspace → same bytes: whatever the hash seed, file creation order or directory-entry order.

The workspace is the shipped ``examples/`` plus a few files that produce
diagnostics. It is built twice at the same path — once creating files in
sorted order, once in reverse — and the tool is run under different
``PYTHONHASHSEED`` values, the second time with a shim that hands the tool
every directory listing in a shuffled order (file systems differ in how
creation order shows in ``readdir``; the shim makes the test independent of
that), and with the analysis in one process, then in several (:mod:`.forked`). Graph JSON and DOT, ``check``'s JSON and its SARIF must be identical.
The graph output must also be identical from another root path and mention
no absolute path of the machine.
"""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

REPO = Path(__file__).resolve().parents[1]
EXAMPLES = REPO / "examples"
HANG_GUARD_S = 300

#: Extra files with diagnostics (relative path → bytes); the broken link is added separately.
EXTRA_FILES: dict[str, bytes] = {
    "src/extra/broken_syntax.py": b"import rclpy\ndef broken(:\n",
    "src/extra/latin.py": b"import rclpy\nx = '\xe9'\n",
    "src/extra/deep.py": ("import rclpy\nx = " + " + ".join(["'a'"] * 900) + "\n").encode(),
    "src/extra/duplicate/talker.py": b"import rclpy\nrclpy.create_node('talker_twin')\n",
    "stubs/broken.toml": b'[functions."x.y"]\nparams = 5\n',
    # An included launch file chosen on two branches (one description source per branch).
    "src/extra/launch/lidar.launch.py": (
        b"import os\n\nfrom launch import LaunchDescription\n"
        b"from launch.actions import IncludeLaunchDescription\n"
        b"from launch.launch_description_sources import PythonLaunchDescriptionSource\n"
        b"from launch.substitutions import LaunchConfiguration\n\n\n"
        b"def generate_launch_description():\n"
        b"    if os.environ.get('LIDAR_MODEL', 'a') == 'a':\n"
        b"        source = PythonLaunchDescriptionSource(\n"
        b"            [LaunchConfiguration('lidar_dir', default='/opt/a'), '/a.launch.py'])\n"
        b"    else:\n"
        b"        source = PythonLaunchDescriptionSource(\n"
        b"            [LaunchConfiguration('lidar_dir', default='/opt/b'), '/b.launch.py'])\n"
        b"    return LaunchDescription([IncludeLaunchDescription(source)])\n"),
    "src/extra_cpp/package.xml": b"<package format=\"3\"><name>extra_cpp</name></package>\n",
    "src/extra_cpp/src/relay.cpp": b'#include "rclcpp/rclcpp.hpp"\nclass Relay : public rclcpp::Node {\n'
                                   b'public:\n  Relay() : Node("relay") {\n'
                                   b'    create_publisher<std_msgs::msg::String>("chatter_relay", 10);\n'
                                   b'    create_subscription<std_msgs::msg::String>(declare_parameter("in", "chatter"), 10, cb);\n'
                                   b'  }\n  void broken(\n};\n',
}

#: Runs the tool with os.scandir / os.listdir answering in a seeded random order.
SHUFFLING_LAUNCHER = """
import os, random, runpy, sys

rng = random.Random(int(os.environ["ROSGRAPH_TEST_SHUFFLE_SEED"]))
real_scandir, real_listdir = os.scandir, os.listdir


class Shuffled:
    def __init__(self, path="."):
        with real_scandir(path) as entries:
            self.entries = list(entries)
        rng.shuffle(self.entries)

    def __iter__(self):
        return self

    def __next__(self):
        if not self.entries:
            raise StopIteration
        return self.entries.pop()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False

    def close(self):
        pass


def listdir(path="."):
    names = real_listdir(path)
    rng.shuffle(names)
    return names


os.scandir, os.listdir = Shuffled, listdir
sys.argv = ["flake8-rosgraph", *sys.argv[1:]]
runpy.run_module("flake8_rosgraph", run_name="__main__", alter_sys=True)
"""


def _files_to_copy() -> list[tuple[str, bytes]]:
    out = [(p.relative_to(EXAMPLES).as_posix(), p.read_bytes())
           for p in sorted(EXAMPLES.rglob("*")) if p.is_file() and "__pycache__" not in p.parts]
    return out + sorted(EXTRA_FILES.items())


def build_workspace(root: Path, reverse: bool) -> None:
    """Create the workspace at ``root``, making folders and files in sorted or reverse-sorted order."""
    files = _files_to_copy()
    if reverse:
        files.reverse()
    for rel, content in files:
        target = root / rel
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(content)
    link = root / "src" / "extra" / "dangling.py"
    if hasattr(os, "symlink"):
        link.symlink_to(root / "src" / "extra" / "missing_target.py")


def tool(args: list[str], cwd: Path, hash_seed: str, shuffle_seed: str | None) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items() if not k.startswith("ROSGRAPH_")}
    env["PYTHONHASHSEED"] = hash_seed
    if shuffle_seed is None:
        argv = [sys.executable, "-m", "flake8_rosgraph", *args]
    else:
        env["ROSGRAPH_TEST_SHUFFLE_SEED"] = shuffle_seed
        argv = [sys.executable, "-c", SHUFFLING_LAUNCHER, *args]
    done = subprocess.run(argv, cwd=cwd, env=env, capture_output=True, timeout=HANG_GUARD_S)
    assert b"Traceback" not in done.stderr, done.stderr.decode(errors="replace")
    return done


def outputs(root: Path, scratch: Path, hash_seed: str, shuffle_seed: str | None, jobs: str) -> dict[str, bytes]:
    """Every machine-readable output of the tool on ``root`` (cache in ``scratch``, never shared),
    its analysis using up to ``jobs`` processes."""
    out: dict[str, bytes] = {}
    for fmt in ("json", "dot"):
        done = tool(["graph", ".", "--format", fmt, "--stubs", "stubs/broken.toml", "--jobs", jobs],
                    root, hash_seed, shuffle_seed)
        assert done.returncode == 0, done.stderr.decode(errors="replace")
        out[f"graph.{fmt}"] = done.stdout
        out[f"graph.{fmt}.stderr"] = done.stderr
    check_help = tool(["check", "--help"], root, hash_seed, None)
    if check_help.returncode == 0:
        cache_dir = scratch / f"cache-{hash_seed}-{shuffle_seed}"
        sarif = scratch / f"out-{hash_seed}-{shuffle_seed}.sarif"
        done = tool(["check", ".", "--root", ".", "--format", "json", "--cache-dir", str(cache_dir),
                     "--sarif", str(sarif), "--jobs", jobs], root, hash_seed, shuffle_seed)
        assert done.returncode in (0, 1), done.stderr.decode(errors="replace")
        out["check.json"] = done.stdout
        out["check.sarif"] = sarif.read_bytes()
    return out


@pytest.fixture(scope="module")
def runs(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    base = tmp_path_factory.mktemp("determinism")
    root = base / "ws"
    build_workspace(root, reverse=False)
    first = outputs(root, base, hash_seed="0", shuffle_seed=None, jobs="1")
    shutil.rmtree(root)
    build_workspace(root, reverse=True)
    second = outputs(root, base, hash_seed="4242", shuffle_seed="7", jobs="3")  # groups in 3 processes
    elsewhere = base / "somewhere" / "else" / "ws"
    build_workspace(elsewhere, reverse=True)
    moved = outputs(elsewhere, base, hash_seed="99", shuffle_seed="3", jobs="2")
    return {"first": first, "second": second, "moved": moved, "root": root, "elsewhere": elsewhere}


def test_examples_are_present() -> None:
    assert len(_files_to_copy()) > 20, "examples/ missing: the determinism workspace would be trivial"


@pytest.mark.parametrize("name", ["graph.json", "graph.dot", "graph.json.stderr", "check.json", "check.sarif"])
def test_same_bytes_across_hash_seeds_and_entry_orders(runs: dict[str, Any], name: str) -> None:
    first, second = runs["first"], runs["second"]
    if name not in first:
        pytest.skip("the check subcommand is not available")
    assert first[name] == second[name], f"{name} differs between runs"


@pytest.mark.parametrize("name", ["graph.json", "graph.dot", "graph.json.stderr"])
def test_same_graph_from_another_root_path(runs: dict[str, Any], name: str) -> None:
    assert runs["first"][name] == runs["moved"][name], f"{name} depends on where the workspace is"


def test_output_is_not_trivial(runs: dict[str, Any]) -> None:
    graph = json.loads(runs["first"]["graph.json"])
    assert len(graph["nodes"]) >= 5
    messages = " ".join(d["message"] for d in graph["diagnostics"])
    assert "syntax error" in messages and "cannot decode" in messages and "stub" in messages


def test_no_absolute_paths_of_this_machine_in_graph_json(runs: dict[str, Any]) -> None:
    machine_paths = {str(runs["root"]), str(runs["elsewhere"]), str(REPO), str(Path.home()), sys.prefix,
                     sys.base_prefix, os.getcwd(), str(Path(sys.executable).parent)}
    machine_paths = {p.replace(os.sep, "/") for p in machine_paths if len(Path(p).parts) >= 2}
    for run in ("first", "moved"):
        text = runs[run]["graph.json"].decode("utf-8")
        for path in sorted(machine_paths):
            assert path not in text, f"graph JSON mentions {path}"
        graph = json.loads(text)
        file_paths = [n["path"] for n in graph["nodes"]] + [d["path"] for d in graph["diagnostics"]]
        file_paths += [e["path"] for n in graph["nodes"] for kind in n if isinstance(n[kind], list)
                       for e in n[kind]]
        for path in file_paths:
            assert not os.path.isabs(path) and not path.startswith("/"), f"absolute path {path!r} in graph JSON"
            assert "\\" not in path, f"non-POSIX path {path!r} in graph JSON"


def test_the_shuffling_launcher_really_shuffles(tmp_path: Path) -> None:
    """Guard for the test itself: under the shim, two listings of one folder come back in different orders."""
    for i in range(40):
        (tmp_path / f"f{i:02}.py").write_text("")
    probe = SHUFFLING_LAUNCHER.split("sys.argv = ")[0] + (
        "print(os.listdir('.') != os.listdir('.') or "
        "[e.name for e in os.scandir('.')] != [e.name for e in os.scandir('.')])\n")
    env = dict(os.environ, ROSGRAPH_TEST_SHUFFLE_SEED="5")
    done = subprocess.run([sys.executable, "-c", probe], cwd=tmp_path, env=env, capture_output=True, text=True,
                          timeout=HANG_GUARD_S)
    assert done.stdout.strip() == "True", done.stderr
