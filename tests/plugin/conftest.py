"""Shared helpers for the flake8 adapter, cache, SARIF and integration tests.

Most tests run against the fake analysis in ``fake_site/`` (see its docstring),
so they test the adapter and not the extractor; the acceptance tests on
``examples/`` use the real one.
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap
import types
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
FAKE_SITE = HERE / "fake_site"
REPO = HERE.parents[1]
EXAMPLES = REPO / "examples"


def _sarif_schema() -> Path:
    """The official SARIF 2.1.0 schema, which lives outside the project (never copied in):
    ``$ROSGRAPH_SARIF_SCHEMA``, else ``shared/schemas/`` beside the repository or beside
    any folder above it (CI runs in a fresh clone somewhere else on the same machine)."""
    env = os.environ.get("ROSGRAPH_SARIF_SCHEMA")
    if env:
        return Path(env)
    relative = Path("shared") / "schemas" / "sarif-schema-2.1.0.json"
    for folder in [REPO, *REPO.parents, Path("/work")]:
        if (folder / relative).is_file():
            return folder / relative
    return REPO.parent / relative


SARIF_SCHEMA = _sarif_schema()

#: The standard fake workspace: two packages, findings the fake rules report:
#: talker.py:6 ROS001 '/orphan', talker.py:7 ROS002 '/loop' (publisher at line 8),
#: listener.py:7 ROS003 '/nobody'; listener.py:6 carries '# noqa: ROS003'.
TALKER = """\
from std_msgs.msg import String


def make(node):
    node.create_publisher(String, 'chatter', 10)
    node.create_publisher(String, 'orphan', 10)
    node.create_subscription(String, 'loop', print, 10)
    node.create_publisher(String, 'loop', 10)
"""
LISTENER = """\
from std_msgs.msg import String


def make(node):
    node.create_subscription(String, 'chatter', print, 10)
    node.create_subscription(String, 'unheard', print, 10)  # noqa: ROS003
    node.create_subscription(String, 'nobody', print, 10)
"""
EXPECTED_STANDARD = [
    ("src/pkg_a/pkg_a/talker.py", 6, 10, "ROS001"),
    ("src/pkg_a/pkg_a/talker.py", 7, 10, "ROS002"),
    ("src/pkg_b/pkg_b/listener.py", 7, 10, "ROS003"),
]
#: What the analysis itself finds: ``# noqa`` is for the front ends to apply.
RAW_STANDARD = sorted(EXPECTED_STANDARD + [("src/pkg_b/pkg_b/listener.py", 6, 10, "ROS003")])


def write_tree(root: Path, files: dict[str, str]) -> Path:
    for relative, text in files.items():
        path = root / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(textwrap.dedent(text), encoding="utf-8")
    return root


def standard_files() -> dict[str, str]:
    return {
        "src/pkg_a/package.xml": "<package><name>pkg_a</name></package>\n",
        "src/pkg_a/pkg_a/__init__.py": "",
        "src/pkg_a/pkg_a/talker.py": TALKER,
        "src/pkg_b/package.xml": "<package><name>pkg_b</name></package>\n",
        "src/pkg_b/pkg_b/__init__.py": "",
        "src/pkg_b/pkg_b/listener.py": LISTENER,
    }


@pytest.fixture
def workspace(tmp_path: Path) -> Path:
    """A colcon-style workspace (``ws/src/<pkg>``) with the standard fake findings."""
    return write_tree(tmp_path / "ws", standard_files())


@pytest.fixture
def fake_engine(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> Path:
    """Install the fake analysis in this process; returns the analysis log file."""
    monkeypatch.syspath_prepend(str(FAKE_SITE))
    import rosgraph_fakes
    import flake8_rosgraph.rules as rules

    analysis = types.ModuleType("flake8_rosgraph.analysis")
    analysis.build_graph = rosgraph_fakes.build_graph
    monkeypatch.setitem(sys.modules, "flake8_rosgraph.analysis", analysis)
    monkeypatch.setattr(rules, "run_rules", rosgraph_fakes.run_rules)
    log = tmp_path / "analyses.log"
    monkeypatch.setenv("FAKE_ROSGRAPH_LOG", str(log))
    for name in ("ROSGRAPH_ROOT", "ROSGRAPH_STUBS", "ROSGRAPH_EXTERNAL_TOPICS", "ROSGRAPH_SARIF",
                 "ROSGRAPH_CACHE_DIR", "ROSGRAPH_DEBUG"):
        monkeypatch.delenv(name, raising=False)
    return log


def analyses(log: Path) -> list[str]:
    """The analyses the fake engine ran (one line each)."""
    return log.read_text(encoding="utf-8").splitlines() if log.exists() else []


def clean_env(**extra: str) -> dict[str, str]:
    """The environment for a subprocess: no ROSGRAPH_* from the caller, plus ``extra``."""
    env = {k: v for k, v in os.environ.items() if not k.startswith(("ROSGRAPH_", "FAKE_ROSGRAPH_"))}
    env.pop("PYTHONPATH", None)
    env.update(extra)
    return env


def fake_env(log: Path, **extra: str) -> dict[str, str]:
    """A subprocess environment in which every Python process uses the fake analysis."""
    return clean_env(PYTHONPATH=str(FAKE_SITE), FAKE_ROSGRAPH_LOG=str(log), **extra)


#: Runs flake8's command line under a chosen multiprocessing start method.
_FLAKE8_UNDER = (
    "import multiprocessing, sys\n"
    "method = sys.argv.pop(1)\n"
    "if method != 'default':\n"
    "    multiprocessing.set_start_method(method)\n"
    "from flake8.main.cli import main\n"
    "sys.exit(main(sys.argv[1:]))\n"
)


def run_flake8(args: list[str], cwd: Path, env: dict[str, str], python: str = sys.executable,
               start_method: str = "default") -> subprocess.CompletedProcess[str]:
    """flake8 in a subprocess (isolated from user config files)."""
    return subprocess.run([python, "-c", _FLAKE8_UNDER, start_method, "--isolated", *args],
                          cwd=cwd, env=env, capture_output=True, text=True, timeout=600)


def parse_flake8(stdout: str) -> list[tuple[str, int, int, str]]:
    """``path:line:col: CODE text`` lines → sorted (posix path without ./, line, col, code)."""
    rows = []
    for line in stdout.splitlines():
        path, lineno, col, rest = line.split(":", 3)
        rows.append((Path(path).as_posix().removeprefix("./"), int(lineno), int(col), rest.split()[0]))
    return sorted(rows)


def validate_sarif(log: dict) -> None:
    """Validate against the official SARIF 2.1.0 schema and GitHub's upload limits, or skip saying why."""
    check_github_limits(log)
    if not SARIF_SCHEMA.is_file():
        pytest.skip(f"SARIF schema not found at {SARIF_SCHEMA} (the shared/ folder beside the repo)")
    import jsonschema

    jsonschema.validate(log, json.loads(SARIF_SCHEMA.read_text(encoding="utf-8")))


def check_github_limits(log: dict) -> None:
    """What GitHub code scanning refuses on upload (docs: "SARIF support for code scanning", limits)."""
    import gzip

    assert len(gzip.compress(json.dumps(log).encode())) <= 10 * 1024 * 1024, "compressed file over 10 MB"
    assert len(log["runs"]) <= 20
    identities = [(run["tool"]["driver"]["name"], run.get("automationDetails", {}).get("id")) for run in log["runs"]]
    assert len(identities) == len(set(identities)), "two runs with one tool and category are rejected"
    for run in log["runs"]:
        rules = run["tool"]["driver"].get("rules", [])
        assert len(run["results"]) <= 25_000 and len(rules) <= 25_000
        assert all(len(rule.get("properties", {}).get("tags", [])) <= 20 for rule in rules)
        for result in run["results"]:
            assert len(result["locations"]) <= 1_000 and len(result.get("relatedLocations", [])) <= 1_000
            assert result["partialFingerprints"]["primaryLocationLineHash"]
            for location in result["locations"] + result.get("relatedLocations", []):
                artifact = location["physicalLocation"]["artifactLocation"]
                uri = artifact["uri"]
                assert (artifact.get("uriBaseId") == "%SRCROOT%" and not uri.startswith("/")
                        and "://" not in uri) or uri.startswith("file:///"), uri


@pytest.fixture(scope="session")
def flake8_401_venv(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A virtual env with flake8 4.0.1 (pulled in by ament_flake8, which pins it) and this package.

    Proves the plugin on the oldest supported flake8 and hosts the ament_flake8
    test. Needs PyPI, like any fresh install.
    """
    if sys.version_info >= (3, 12):
        pytest.skip("flake8 4.0.1 (ROS 2 Humble's) does not run on Python >= 3.12 "
                    "(importlib.metadata API); the Python 3.10 CI leg covers it")
    venv = tmp_path_factory.mktemp("venv-flake8-401")
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True, timeout=300)
    python = venv / "bin" / "python"
    subprocess.run([str(python), "-m", "pip", "install", "--quiet", "--disable-pip-version-check",
                    "ament-lint-flake8", "flake8==4.0.1", str(REPO)], check=True, timeout=900,
                   env=clean_env())
    return python
