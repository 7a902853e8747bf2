"""Groups of modules analysed in forked processes: the same graph as one process gives, whatever
happens to a child (:mod:`flake8_rosgraph.forked`, :func:`flake8_rosgraph.analysis.build_graph`)."""
from __future__ import annotations

import os
import pickle
import subprocess
import sys
import threading
from pathlib import Path

import pytest

from flake8_rosgraph import analysis, forked
from flake8_rosgraph.analysis import build_graph
from flake8_rosgraph.launch.api import graph_to_json_obj

pytestmark = pytest.mark.skipif(not hasattr(os, "fork"), reason="needs os.fork (Unix)")

#: Three packages that import nothing from one another (three groups), one with a helper module
#: and a base class in another module, names from parameters and loops: enough for every kind
#: of fact to cross from a child to the parent.
WORKSPACE = {
    "src/sensors/package.xml": "<package format='3'><name>sensors</name></package>\n",
    "src/sensors/setup.py": (
        "from setuptools import setup\n"
        "setup(name='sensors', packages=['sensors'], entry_points={'console_scripts': [\n"
        "    'ranges = sensors.ranges:main']})\n"),
    "src/sensors/sensors/__init__.py": "",
    "src/sensors/sensors/base.py": (
        "from rclpy.node import Node\n\n\n"
        "class SensorNode(Node):\n"
        "    def __init__(self, name, topics):\n"
        "        super().__init__(name)\n"
        "        self.declare_parameter('rate', 10.0)\n"
        "        self.pubs = [self.make_publisher(topic) for topic in topics]\n\n"
        "    def make_publisher(self, topic):\n"
        "        from sensor_msgs.msg import Range\n"
        "        return self.create_publisher(Range, 'range/' + topic, 10)\n"),
    "src/sensors/sensors/ranges.py": (
        "import rclpy\n"
        "from sensors.base import SensorNode\n\n"
        "SIDES = ['left', 'right', 'front']\n\n\n"
        "def main():\n"
        "    rclpy.init()\n"
        "    node = SensorNode('ranges', SIDES)\n"
        "    rclpy.spin(node)\n"),
    "src/planner/package.xml": "<package format='3'><name>planner</name></package>\n",
    "src/planner/setup.py": (
        "from setuptools import setup\n"
        "setup(name='planner', packages=['planner'], entry_points={'console_scripts': [\n"
        "    'planner = planner.planner:main']})\n"),
    "src/planner/planner/__init__.py": "",
    "src/planner/planner/planner.py": (
        "import rclpy\n"
        "from rclpy.node import Node\n"
        "from sensor_msgs.msg import Range\n"
        "from std_srvs.srv import Trigger\n\n\n"
        "class Planner(Node):\n"
        "    def __init__(self):\n"
        "        super().__init__('planner')\n"
        "        for side in ('left', 'right', 'front'):\n"
        "            self.create_subscription(Range, f'range/{side}', self.on_range, 10)\n"
        "        self.create_service(Trigger, 'replan', self.on_replan)\n\n"
        "    def on_range(self, msg):\n"
        "        self.get_logger().info(str(msg.range))\n\n"
        "    def on_replan(self, request, response):\n"
        "        response.success = True\n"
        "        return response\n\n\n"
        "def main():\n"
        "    rclpy.init()\n"
        "    rclpy.spin(Planner())\n"),
    "src/console/package.xml": "<package format='3'><name>console</name></package>\n",
    "src/console/setup.py": (
        "from setuptools import setup\n"
        "setup(name='console', packages=['console'], entry_points={'console_scripts': [\n"
        "    'console = console.console:main']})\n"),
    "src/console/console/__init__.py": "",
    "src/console/console/console.py": (
        "import rclpy\n"
        "from std_srvs.srv import Trigger\n\n\n"
        "def main():\n"
        "    rclpy.init()\n"
        "    node = rclpy.create_node('console')\n"
        "    client = node.create_client(Trigger, 'replann')\n"
        "    client.wait_for_service()\n"),
}


@pytest.fixture
def workspace(tmp_path: Path) -> Path:
    root = tmp_path / "ws"
    for rel, text in WORKSPACE.items():
        (root / rel).parent.mkdir(parents=True, exist_ok=True)
        (root / rel).write_text(text)
    return root


def _square(job: int) -> bytes:
    return pickle.dumps((os.getpid(), job * job))


def test_every_job_runs_once_in_a_child() -> None:
    with forked.processes(3):
        assert forked.allowed() == 3
        results = forked.ForkedJobs.start(list(range(20)), _square, 3).collect()
    found = {job: pickle.loads(data) for job, data in results.items()}
    assert {job: square for job, (_, square) in found.items()} == {job: job * job for job in range(20)}
    assert os.getpid() not in {pid for pid, _ in found.values()}


def test_a_job_whose_result_cannot_be_sent_is_left_to_the_caller() -> None:
    results = forked.ForkedJobs.start(list(range(6)), lambda job: None if job % 2 else bytes([job]), 2).collect()
    assert results == {0: b"\x00", 2: b"\x02", 4: b"\x04"}


def test_a_child_that_dies_loses_only_the_job_it_was_on() -> None:
    def work(job: int) -> bytes:
        if job == 3:
            os._exit(7)  # the child dies mid-job; the other takes the rest of the queue
        return bytes([job])

    results = forked.ForkedJobs.start(list(range(8)), work, 2).collect()
    assert 3 not in results
    assert {job: data for job, data in results.items()} == {job: bytes([job]) for job in results}
    assert len(results) >= 4  # the surviving child went on with the queue


def _no_process(*_args: object) -> int:
    raise BlockingIOError(11, "Resource temporarily unavailable")  # what fork raises at a process limit


def test_without_processes_to_be_had_every_job_is_left_to_the_caller(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(os, "fork", _no_process)
    assert forked.ForkedJobs.start(list(range(5)), lambda job: b"done", 2).collect() == {}


def test_one_process_unless_the_run_allows_more_and_no_other_thread_runs() -> None:
    assert forked.allowed() == 1  # nobody said
    release = threading.Event()
    other = threading.Thread(target=release.wait)
    with forked.processes(4):
        assert forked.allowed() == 4
        other.start()
        try:
            assert forked.allowed() == 1  # a child forked beside a thread may inherit a held lock
        finally:
            release.set()
            other.join()
    assert forked.allowed() == 1


def test_no_more_processes_than_can_shorten_the_run() -> None:
    with forked.processes(16):
        assert forked.useful([]) == 0
        assert forked.useful([500]) == 0  # one job and nothing else to do: the caller runs it
        assert forked.useful([1] * 40) == forked.MAX_PROCESSES  # memory bounds the children
        assert forked.useful([60, 20, 20, 20]) == 2  # the heaviest job takes half the run anyway
        assert forked.useful([10, 10, 10]) == 3
    with forked.processes(2):
        assert forked.useful([10, 10, 10]) == 2
    assert forked.useful([10, 10, 10]) == 0  # the run allowed one process


def test_one_job_goes_to_a_child_only_when_the_caller_has_as_much_to_do_meanwhile() -> None:
    with forked.processes(2):
        assert forked.useful([500], meanwhile=600) == 1  # an edited group beside reading the kept ones
        assert forked.useful([500], meanwhile=forked.MIN_OVERLAP - 1) == 0  # not worth a fork
        assert forked.useful([forked.MIN_OVERLAP - 1], meanwhile=600) == 0  # a tiny group: the same
    assert forked.useful([500], meanwhile=600) == 0


def _graph_json(root: Path, processes: int) -> dict:
    with forked.processes(processes):
        return graph_to_json_obj(build_graph(root))


def test_groups_analysed_in_children_give_the_graph_one_process_gives(workspace: Path,
                                                                      monkeypatch: pytest.MonkeyPatch) -> None:
    started: list[int] = []
    real_start = forked.ForkedJobs.start

    def spy(order, work, count):
        started.append(len(order))
        return real_start(order, work, count)

    monkeypatch.setattr(forked.ForkedJobs, "start", spy)
    alone = _graph_json(workspace, 1)
    assert started == []
    together = _graph_json(workspace, 3)
    assert len(started) == 1 and started[0] >= 3  # the packages' groups (and setup.py files), in children
    assert together == alone
    assert {"ranges", "planner", "console"} <= {node["name"] for node in alone["nodes"]}


def test_a_group_whose_child_died_is_analysed_by_the_parent(workspace: Path,
                                                            monkeypatch: pytest.MonkeyPatch) -> None:
    alone = _graph_json(workspace, 1)
    parent = os.getpid()
    real_facts = analysis._Group.facts

    def dies_in_a_child(self, library, memo, kept):
        if os.getpid() != parent and any(name.startswith("planner") for name in self.program.modules):
            os._exit(9)
        return real_facts(self, library, memo, kept)

    monkeypatch.setattr(analysis._Group, "facts", dies_in_a_child)
    assert _graph_json(workspace, 2) == alone


def test_a_run_that_can_have_no_process_analyses_every_group_itself(workspace: Path,
                                                                    monkeypatch: pytest.MonkeyPatch) -> None:
    alone = _graph_json(workspace, 1)
    monkeypatch.setattr(os, "fork", _no_process)
    assert _graph_json(workspace, 3) == alone


def test_children_keep_the_groups_they_analysed_for_the_next_run(workspace: Path, tmp_path: Path) -> None:
    """``check`` with the cache: the facts children computed are in the cache, and the next run
    (which analyses nothing) reports the same findings."""
    def check(cache: Path, jobs: str) -> subprocess.CompletedProcess:
        env = {k: v for k, v in os.environ.items() if not k.startswith("ROSGRAPH_")}
        return subprocess.run([sys.executable, "-m", "flake8_rosgraph", "check", str(workspace), "--cache-dir",
                               str(cache), "--format", "json", "--jobs", jobs],
                              capture_output=True, text=True, env=env, timeout=300)

    serial = check(tmp_path / "serial", "1")
    cache = tmp_path / "cache"
    first = check(cache, "2")
    assert first.returncode == 1, first.stderr  # the console's misspelt service
    assert "replann" in first.stdout and first.stdout == serial.stdout
    kept = sorted(entry.name for entry in (cache / "groups").glob("*.json"))
    assert kept == sorted(entry.name for entry in (tmp_path / "serial" / "groups").glob("*.json"))
    assert len(kept) >= 3
    for entry in (cache).glob("*.json"):
        entry.unlink()  # the workspace report: the next run must put it together from the groups
    assert check(cache, "2").stdout == first.stdout


def test_an_edited_group_is_analysed_in_a_child_while_the_kept_groups_are_read(
        workspace: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The pre-commit case: one group changed, the others kept. Its analysis overlaps with reading
    the kept facts (the thresholds are lowered: the groups here are a few lines each)."""
    from flake8_rosgraph.facts_cache import FactsStore

    store = FactsStore(tmp_path / "groups", b"secret", "context")
    store.folder.mkdir()
    with forked.processes(1):
        build_graph(workspace, facts_memo=store)  # every group kept
    console = workspace / "src/console/console/console.py"
    console.write_text(console.read_text().replace("'replann'", "'replan'"))
    alone = _graph_json(workspace, 1)
    started: list[tuple[list[int], int]] = []
    real_start = forked.ForkedJobs.start

    def spy(order, work, count):
        started.append((list(order), count))
        return real_start(order, work, count)

    monkeypatch.setattr(forked.ForkedJobs, "start", spy)
    monkeypatch.setattr(analysis, "KEPT_READ_RATIO", 1)
    monkeypatch.setattr(forked, "MIN_OVERLAP", 1)
    with forked.processes(2):
        edited = graph_to_json_obj(build_graph(workspace, facts_memo=store))
    assert [(len(order), count) for order, count in started] == [(1, 1)]  # the console's group, one child
    assert edited == alone
    console_node = next(node for node in edited["nodes"] if node["name"] == "console")
    assert [client["name"] for client in console_node["clients"]] == ["/replan"]  # the edit shows
