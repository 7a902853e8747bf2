"""Running the tool on hostile workspaces, and the checks every such run must pass.

Every run is a subprocess with a hang guard (a generous timeout, never a speed
claim) and an address-space cap, so that a runaway analysis fails its own test
instead of freezing or swapping out the machine the suite runs on.
"""
from __future__ import annotations

import importlib.util
import json
import os
import re
import shutil
import signal
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Iterable, Mapping, Sequence

import pytest

#: Seconds a single tool run may take before the test calls it a hang.
HANG_GUARD_S = 120
#: Address-space cap of a tool run: far above what a real analysis needs, far below a machine's RAM.
MEMORY_CAP_BYTES = 4 * 1024 ** 3

#: Environment variables of the tool that must not leak from the developer's shell into a test run.
_TOOL_ENV_PREFIX = "ROSGRAPH_"


@dataclass(frozen=True)
class Run:
    """What a finished tool run left behind."""

    args: tuple[str, ...]
    returncode: int
    stdout: str
    stderr: str

    def explain(self) -> str:
        return (f"command: {' '.join(self.args)}\nexit status: {self.returncode}\n"
                f"--- stderr ---\n{self.stderr[-4000:]}\n--- stdout ---\n{self.stdout[:2000]}")


def _memory_limiter(cap: int):
    def limit() -> None:  # runs in the child, before exec
        import resource
        resource.setrlimit(resource.RLIMIT_AS, (cap, cap))
    return limit


def clean_env(**extra: str) -> dict[str, str]:
    """The current environment minus the tool's own variables, plus ``extra``."""
    env = {k: v for k, v in os.environ.items() if not k.startswith(_TOOL_ENV_PREFIX)}
    env.update(extra)
    return env


def run(argv: Sequence[str], cwd: Path, env: Mapping[str, str] | None = None,
        hang_is_failure: bool = True, memory_cap: int = MEMORY_CAP_BYTES,
        hang_guard: float = HANG_GUARD_S) -> Run | None:
    """Run ``argv`` under the hang guard and the memory cap; a hang fails the calling test
    (or, with ``hang_is_failure=False``, returns ``None``).

    The child leads its own process group, so that on a hang its helpers (flake8's
    worker processes) are killed with it instead of lingering blocked.
    """
    posix = os.name == "posix"
    child = subprocess.Popen(list(argv), cwd=cwd, env=dict(env) if env is not None else clean_env(),
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, errors="replace",
                             preexec_fn=_memory_limiter(memory_cap) if posix else None,
                             start_new_session=posix)
    try:
        stdout, stderr = child.communicate(timeout=hang_guard)
    except subprocess.TimeoutExpired:
        _kill_group(child)
        if not hang_is_failure:
            return None
        pytest.fail(f"hang: {' '.join(argv)} did not finish within {hang_guard} s (cwd {cwd})",
                    pytrace=False)
    return Run(tuple(argv), child.returncode, stdout, stderr)


def _kill_group(child: subprocess.Popen) -> None:
    if os.name == "posix":
        try:
            os.killpg(child.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    else:
        child.kill()
    child.communicate()


def graph_cli(path: Path, *options: str, cwd: Path, env: Mapping[str, str] | None = None) -> Run:
    """``python -m flake8_rosgraph graph PATH OPTIONS`` (the documented command line)."""
    return run([sys.executable, "-m", "flake8_rosgraph", "graph", str(path), *options], cwd, env)


def flake8_executable() -> str:
    """The flake8 console script of the interpreter running the tests."""
    name = "flake8.exe" if os.name == "nt" else "flake8"
    beside = Path(sys.executable).with_name(name)
    return str(beside) if beside.exists() else (shutil.which("flake8") or name)


def flake8_cli(workspace: Path, *options: str) -> Run:
    """``flake8 --select ROS <ws>`` run from inside the workspace, ignoring user configuration."""
    return run([flake8_executable(), "--isolated", "--select", "ROS", *options, str(workspace)], workspace)


#: flake8 with this project's plugin replaced by one that finds nothing: what flake8 alone does.
_FLAKE8_WITHOUT_PLUGIN = """
import sys, types
fake = types.ModuleType("flake8_rosgraph.plugin")


class RosGraphChecker:
    name = "flake8-rosgraph"
    version = "0"

    def __init__(self, tree):
        pass

    def run(self):
        return iter(())


fake.RosGraphChecker = RosGraphChecker
sys.modules["flake8_rosgraph.plugin"] = fake
from flake8.main.cli import main
sys.argv[0] = "flake8"
sys.exit(main())
"""


def flake8_core_failure(workspace: Path, *options: str) -> str | None:
    """Why flake8 itself — its parser, pyflakes, pycodestyle, without this plugin — fails on ``workspace``.

    ``None`` when it copes. The same command line as :func:`flake8_cli`, with the
    plugin swapped for an empty one; each flake8 version has its own weak spots
    (4.0.1 lets ``ast.parse``'s ValueError escape, 7.x a RecursionError).
    """
    done = run([sys.executable, "-c", _FLAKE8_WITHOUT_PLUGIN, "--isolated", "--select", "ROS", *options,
                str(workspace)], workspace, hang_is_failure=False)
    if done is None:
        return (f"flake8 itself, without this plugin, does not finish within {HANG_GUARD_S} s "
                f"here on Python {sys.version.split()[0]}")
    output = done.stdout + done.stderr
    if done.returncode in (0, 1) and "Traceback" not in output and "failed during execution" not in output:
        return None
    last = (done.stderr.strip().splitlines() or done.stdout.strip().splitlines()
            or [f"exit status {done.returncode}"])[-1]
    return f"flake8 itself, without this plugin, fails here on Python {sys.version.split()[0]}: {last[:160]}"


def plugin_available() -> bool:
    """Whether the flake8 adapter module exists (it is written in parallel with these tests)."""
    return importlib.util.find_spec("flake8_rosgraph.plugin") is not None


# -- what every run must satisfy ----------------------------------------------------------------

def assert_clean_exit(done: Run, allowed: Iterable[int] = (0,)) -> None:
    """Exit status in ``allowed``, no traceback, no internal error, no crash by signal."""
    assert done.returncode in tuple(allowed), f"unexpected exit status\n{done.explain()}"
    assert "Traceback (most recent call last)" not in done.stderr + done.stdout, done.explain()
    assert "internal error" not in done.stderr, f"the analyser failed as a whole\n{done.explain()}"


def parse_graph(done: Run) -> dict[str, Any]:
    """The graph JSON on stdout, checked against the parts of the contract a hostile input could break."""
    try:
        graph = json.loads(done.stdout)
    except ValueError as exc:
        raise AssertionError(f"stdout is not JSON ({exc})\n{done.explain()}") from None
    assert graph.get("schema") == "rosgraph/1", done.explain()
    for diag in graph.get("diagnostics", ()):
        assert "\n" not in diag["message"], f"diagnostic spans several lines: {diag!r}"
        assert not diag["path"].startswith("/") and not re.match(r"^[A-Za-z]:[\\/]", diag["path"]), \
            f"diagnostic names an absolute path: {diag!r}"
        if diag["severity"] == "info":
            continue  # informational (precision bounds): on stderr only with --verbose
        shown = f"{diag['path']}:{diag['line']}: " if diag["path"] else ""
        assert f"{shown}{diag['severity']}: {diag['message']}" in done.stderr, \
            f"diagnostic not shown on stderr: {diag!r}\n{done.explain()}"
    return graph


def entity_keys(graph: Mapping[str, Any]) -> set[tuple[str | None, str, Any, str, int]]:
    """Every entity as ``(node fqn, kind, name-or-period, path, line)``; nodes as kind ``node``."""
    out: set[tuple[str | None, str, Any, str, int]] = set()
    for node in graph["nodes"]:
        out.add((node["fqn"], "node", node["name"], node["path"], node["line"]))
        for kind in ("publishers", "subscriptions", "services", "clients", "action_servers",
                     "action_clients", "timers", "parameters"):
            for ent in node.get(kind, ()):
                name = ent.get("topic", ent.get("name", ent.get("period")))
                out.add((node["fqn"], kind, name, ent["path"], ent["line"]))
    return out


def diagnostics_on(graph: Mapping[str, Any], path: str) -> list[dict[str, Any]]:
    return [d for d in graph.get("diagnostics", ()) if d["path"] == path]
