"""Budgets are local: a hostile package costs only its own results, never its neighbour's.

One workspace holds a correct ROS 2 package (two nodes over several modules, a
publisher created in a timer callback, a type clash and a self-loop to report)
next to a hostile package made of every construct that makes an abstract
interpreter work without end: a 12,000-line chain of mutually recursive helpers
called with growing arguments, loops that grow names without bound, a class
with a metaclass and ``exec``, and the analyser-stress files of
:mod:`.hostile_inputs`. The correct package's findings must all come out —
through ``check`` and through a real flake8 subprocess — quickly, and each
hostile construct that exhausts its module's budget must be named by a
diagnostic giving the module and the function that consumed it.
"""
from __future__ import annotations

import sys
import time
from pathlib import Path

import pytest

from .harness import assert_clean_exit, entity_keys, flake8_cli, graph_cli, parse_graph, plugin_available, run
from .hostile_inputs import DYNAMIC_PYTHON, GROWING_LOOPS, RECURSION, line_of, write_files

#: The whole hostile workspace, analysed from cold: far below the 20 s the issue allows.
TIME_LIMIT_S = 20.0

GOOD_NAMES = """\
TOPIC = 'odom'
STATUS = 'status'
"""

GOOD_BASE = """\
from rclpy.node import Node
from std_msgs.msg import String

from good_pkg.names import STATUS


class Reporting(Node):
    def __init__(self, name):
        super().__init__(name)
        self.status = self.create_publisher(String, STATUS, 10)
        self.status_echo = self.create_subscription(String, STATUS, self.on_status, 10)

    def on_status(self, msg):
        self.get_logger().info(msg.data)
"""

GOOD_ODOMETRY = """\
import rclpy
from nav_msgs.msg import Odometry

from good_pkg.base import Reporting
from good_pkg.names import TOPIC


class OdometryPublisher(Reporting):
    def __init__(self):
        super().__init__('odometry_publisher')
        self.odom = self.create_publisher(Odometry, TOPIC, 10)
        self.timer = self.create_timer(0.1, self.tick)

    def tick(self):
        self.odom.publish(Odometry())


def main():
    rclpy.init()
    rclpy.spin(OdometryPublisher())
"""

GOOD_MONITOR = """\
import rclpy
from rclpy.node import Node
from std_msgs.msg import String

from good_pkg.names import TOPIC


class Monitor(Node):
    def __init__(self):
        super().__init__('monitor')
        self.odom = self.create_subscription(String, TOPIC, self.on_odom, 10)
        self.timer = self.create_timer(1.0, self.start_alarm)

    def on_odom(self, msg):
        pass

    def start_alarm(self):
        self.alarm = self.create_publisher(String, 'alarm', 10)


def main():
    rclpy.init()
    rclpy.spin(Monitor())
"""

GOOD_PACKAGE_XML = """\
<?xml version="1.0"?>
<package format="3">
  <name>{name}</name>
  <version>0.0.1</version>
  <description>{name}</description>
  <maintainer email="dev@example.com">dev</maintainer>
  <license>Apache-2.0</license>
  <exec_depend>rclpy</exec_depend>
</package>
"""

GOOD_SETUP = """\
from setuptools import setup

setup(
    name='good_pkg',
    packages=['good_pkg'],
    entry_points={'console_scripts': [
        'odometry = good_pkg.odometry:main',
        'monitor = good_pkg.monitor:main',
    ]},
)
"""


def mutual_recursion_chain(lines: int) -> str:
    """``lines`` lines of helpers calling each other around a ring with ever-growing arguments."""
    count = lines // 5
    out = ["import rclpy", "from std_msgs.msg import String", ""]
    for i in range(count):
        out += [f"def helper_{i}(name, path):",
                "    if len(name) > len(path):",
                f"        return helper_{(i + 1) % count}(name + '_{i}', [path])",
                f"    return helper_{(i * 7 + 3) % count}(path, (name, name))",
                ""]
    out += ["node = rclpy.create_node('chain_' + helper_0('a', 'b'))",
            "node.create_publisher(String, helper_1('c', 'd'), 10)"]
    return "\n".join(out) + "\n"


META_EXEC = """\
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Registry(type):
    def __new__(mcs, name, bases, namespace):
        exec('namespace["made"] = True')
        return super().__new__(mcs, name, bases, namespace)

    def __call__(cls, *args, **kwargs):
        instance = super().__call__(*args, **kwargs)
        exec(f'instance.topic_{len(args)} = "{cls.__name__}"')
        return instance


class Plugin(Node, metaclass=Registry):
    def __init__(self, name):
        super().__init__(name)
        exec('self.pub = self.create_publisher(String, name + "_out", 10)')
        self.next = Plugin(name + '_next')


Plugin('plugin')
"""

UNBOUNDED_NAME = """\
import rclpy
from std_msgs.msg import String


def topics(prefix):
    name = prefix
    while True:
        name = name + '/' + name[-1]
        yield name


node = rclpy.create_node('unbounded')
for topic in topics('t'):
    node.create_publisher(String, topic, 10)
"""

HOSTILE_MODULES: dict[str, str] = {
    "chain.py": mutual_recursion_chain(12_000),
    "meta_exec.py": META_EXEC,
    "unbounded_name.py": UNBOUNDED_NAME,
    "growing_loops.py": GROWING_LOOPS,
    "recursion.py": RECURSION,
    "dynamic_python.py": DYNAMIC_PYTHON,
}


def good_path(module: str) -> str:
    return f"src/good_pkg/good_pkg/{module}"


#: ``(path:line:, code)`` flake8 and ``check`` must report for the good package.
GOOD_FINDINGS: tuple[tuple[str, str], ...] = (
    # /odom: published as Odometry, subscribed as String.
    (f"{good_path('monitor.py')}:{line_of(GOOD_MONITOR, 'create_subscription')}:", "ROS004"),
    # /status: Reporting publishes and subscribes its own topic.
    (f"{good_path('base.py')}:{line_of(GOOD_BASE, 'create_subscription')}:", "ROS002"),
)


def write_workspace(root: Path) -> None:
    files = {
        "src/good_pkg/package.xml": GOOD_PACKAGE_XML.format(name="good_pkg"),
        "src/good_pkg/setup.py": GOOD_SETUP,
        "src/good_pkg/good_pkg/__init__.py": "",
        "src/good_pkg/good_pkg/names.py": GOOD_NAMES,
        "src/good_pkg/good_pkg/base.py": GOOD_BASE,
        "src/good_pkg/good_pkg/odometry.py": GOOD_ODOMETRY,
        "src/good_pkg/good_pkg/monitor.py": GOOD_MONITOR,
        "src/hostile_pkg/package.xml": GOOD_PACKAGE_XML.format(name="hostile_pkg"),
        "src/hostile_pkg/hostile_pkg/__init__.py": "",
        **{f"src/hostile_pkg/hostile_pkg/{name}": text for name, text in HOSTILE_MODULES.items()},
    }
    write_files(root, {rel: text.encode() for rel, text in files.items()})


def write_good_only(root: Path) -> None:
    write_workspace(root)
    for name in HOSTILE_MODULES:
        (root / "src" / "hostile_pkg" / "hostile_pkg" / name).unlink()


def good_entities(graph: dict) -> set:
    return {key for key in entity_keys(graph) if key[3].startswith("src/good_pkg/")}


@pytest.fixture(scope="module")
def workspaces(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, Path]:
    # Two colcon workspaces (``ws/src/<package>``), so each is its own analysis root.
    mixed, alone = tmp_path_factory.mktemp("mixed") / "ws", tmp_path_factory.mktemp("alone") / "ws"
    write_workspace(mixed)
    write_good_only(alone)
    return mixed, alone


def test_good_package_graph_survives_hostile_neighbour(workspaces: tuple[Path, Path]) -> None:
    mixed, alone = workspaces
    expected = good_entities(parse_graph(graph_cli(alone, "--format", "json", cwd=alone.parent)))
    assert ("/monitor", "publishers", "/alarm", good_path("monitor.py"),
            line_of(GOOD_MONITOR, "'alarm'")) in expected
    start = time.monotonic()
    done = graph_cli(mixed, "--format", "json", cwd=mixed.parent)
    elapsed = time.monotonic() - start
    assert_clean_exit(done)
    graph = parse_graph(done)
    assert good_entities(graph) == expected
    assert elapsed < TIME_LIMIT_S, f"hostile workspace took {elapsed:.1f} s"


def test_each_exhausted_module_is_named_with_the_function_that_consumed_it(
        workspaces: tuple[Path, Path]) -> None:
    mixed, _ = workspaces
    graph = parse_graph(graph_cli(mixed, "--format", "json", cwd=mixed.parent))
    stopped = [d for d in graph["diagnostics"] if "stopped: its budget" in d["message"]]
    chain = [d for d in stopped if "module hostile_pkg.chain " in d["message"]]
    assert len(chain) == 1, graph["diagnostics"]
    [diag] = chain
    assert diag["path"] == "src/hostile_pkg/hostile_pkg/chain.py"
    function = diag["message"].split(") in ", 1)[1].split(" ", 1)[0]
    assert function.startswith("helper_")
    assert diag["line"] == line_of(HOSTILE_MODULES["chain.py"], f"def {function}(")
    # Budgets are local: no module of the good package is ever stopped.
    assert not [d for d in graph["diagnostics"] if d["path"].startswith("src/good_pkg/")]


def test_each_construct_not_followed_has_its_diagnostic(workspaces: tuple[Path, Path]) -> None:
    mixed, _ = workspaces
    graph = parse_graph(graph_cli(mixed, "--format", "json", cwd=mixed.parent))
    found = {(d["path"].rsplit("/", 1)[1], d["line"], d["message"].split(" ", 1)[0])
             for d in graph["diagnostics"] if d["severity"] == "warning"}
    meta, dynamic = HOSTILE_MODULES["meta_exec.py"], HOSTILE_MODULES["dynamic_python.py"]
    assert {
        ("meta_exec.py", line_of(meta, "class Plugin("), "the"),        # the metaclass of Plugin …
        ("meta_exec.py", line_of(meta, "exec('self.pub"), "exec()"),
        ("dynamic_python.py", line_of(dynamic, "class Weird("), "the"),
        ("dynamic_python.py", line_of(dynamic, "exec("), "exec()"),
        ("dynamic_python.py", line_of(dynamic, "eval("), "eval()"),
    } <= found
    bounded = {(d["path"].rsplit("/", 1)[1], d["line"]) for d in graph["diagnostics"]
               if "called in more than" in d["message"]}
    recursion = HOSTILE_MODULES["recursion.py"]
    assert {("recursion.py", line_of(recursion, "def grow(")),
            ("recursion.py", line_of(recursion, "def step("))} <= bounded
    # A name grown without bound in a loop is widened: the publisher is there, its topic unknown.
    unbounded = [key for key in entity_keys(graph)
                 if key[3] == "src/hostile_pkg/hostile_pkg/unbounded_name.py" and key[1] == "publishers"]
    assert unbounded and all(key[2] is None for key in unbounded)


def test_what_an_exhausted_module_created_has_unknown_names(workspaces: tuple[Path, Path]) -> None:
    """The chain's publisher was created from unfinished summaries: its topic is unknown,
    never one of the partial names the ring had produced so far."""
    mixed, _ = workspaces
    graph = parse_graph(graph_cli(mixed, "--format", "json", cwd=mixed.parent))
    chain = [key for key in entity_keys(graph) if key[3] == "src/hostile_pkg/hostile_pkg/chain.py"]
    assert chain, "the chain module's node is still in the graph"
    assert all(key[2] is None for key in chain if key[1] == "publishers"), chain


def test_check_reports_every_good_finding(workspaces: tuple[Path, Path]) -> None:
    mixed, _ = workspaces
    done = run([sys.executable, "-m", "flake8_rosgraph", "check", str(mixed)], mixed.parent)
    assert done.returncode == 1, done.explain()
    for where, code in GOOD_FINDINGS:
        assert any(where in line and code in line for line in done.stdout.splitlines()), \
            f"{code} at {where} missing\n{done.explain()}"


@pytest.mark.skipif(not plugin_available(), reason="flake8 plugin not installed")
def test_flake8_reports_every_good_finding(workspaces: tuple[Path, Path]) -> None:
    mixed, _ = workspaces
    done = flake8_cli(mixed)
    assert done.returncode == 1, done.explain()
    for where, code in GOOD_FINDINGS:
        assert any(where in line and code in line for line in done.stdout.splitlines()), \
            f"{code} at {where} missing\n{done.explain()}"
    assert not [line for line in done.stdout.splitlines() if "ROS000" in line], done.explain()
