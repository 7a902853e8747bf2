"""Incremental analysis: groups of modules that import nothing from one another.

The workspace below has three such groups — a sensor package (a driver on a base class
in another module), a navigation package (a monitor subscribing to topics named in a
constants module, one per name in a loop) and a bring-up package's launch file. Each group
is analysed on its own and its facts are kept in the cache, so an edit re-analyses the
edited module's group only, and the report is the same as a cold run's.
"""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from flake8_rosgraph import cache, facts_cache, facts_json
from flake8_rosgraph.absint.engine import Analysis
from flake8_rosgraph.absint.program import Program
from flake8_rosgraph.options import Settings
from flake8_rosgraph.workspace import load_workspace

from test_parameter_named_entities import package
from test_workspace_discovery import write

SENSORS = package("sensors", {
    "base": """
        from rclpy.node import Node


        class SensorNode(Node):
            def __init__(self, name, topic, msg_type):
                super().__init__(name)
                self.output = self.create_publisher(msg_type, topic, 10)
    """,
    "lidar_driver": """
        import rclpy
        from sensor_msgs.msg import LaserScan

        from .base import SensorNode


        class LidarDriver(SensorNode):
            def __init__(self):
                super().__init__('lidar_driver', '/scan', LaserScan)


        def main():
            rclpy.init()
            rclpy.spin(LidarDriver())
    """,
    "contacts": """
        import rclpy
        from std_msgs.msg import Bool

        from sensors.base import SensorNode


        class ContactDriver(SensorNode):
            def __init__(self):
                super().__init__('contact_driver', '/bumper', Bool)
                self.cliff = self.create_publisher(Bool, '/cliff', 10)


        def main():
            rclpy.init()
            rclpy.spin(ContactDriver())
    """,
}, {"lidar_driver": "lidar_driver", "contact_driver": "contacts"})
NAV = package("nav", {
    "topics": """
        SCAN_TOPIC = '/scan'
        CONTACT_TOPICS = ['/bumper', '/cliff']
    """,
    "monitor": """
        import rclpy
        from rclpy.node import Node
        from sensor_msgs.msg import LaserScan
        from std_msgs.msg import Bool

        from nav.topics import CONTACT_TOPICS, SCAN_TOPIC


        class Monitor(Node):
            def __init__(self):
                super().__init__('obstacle_monitor')
                self.create_subscription(LaserScan, SCAN_TOPIC, self.on_scan, 10)
                for topic in CONTACT_TOPICS:
                    self.create_subscription(Bool, topic, self.on_contact, 10)

            def on_scan(self, msg):
                pass

            def on_contact(self, msg):
                pass


        def main():
            rclpy.init()
            rclpy.spin(Monitor())
    """,
}, {"obstacle_monitor": "monitor"})
BRINGUP = {
    "bringup/package.xml": NAV["nav/package.xml"].replace("nav", "bringup"),
    "bringup/launch/robot.launch.py": """
        from launch import LaunchDescription
        from launch_ros.actions import Node


        def generate_launch_description():
            return LaunchDescription([
                Node(package='sensors', executable='lidar_driver'),
                Node(package='nav', executable='obstacle_monitor'),
            ])
    """,
}


@pytest.fixture
def root(tmp_path: Path) -> Path:
    return write(tmp_path / "ws", {**SENSORS, **NAV, **BRINGUP})


@pytest.fixture
def analysed(monkeypatch: pytest.MonkeyPatch) -> list[tuple[str, ...]]:
    """The groups analysed from here on, as the names of their modules."""
    runs: list[tuple[str, ...]] = []
    original = Analysis.run

    def run(self: Analysis) -> None:
        runs.append(tuple(sorted(self.program.modules)))
        original(self)

    monkeypatch.setattr(Analysis, "run", run)
    return runs


def _report(root: Path) -> list[tuple[str, int, str, str]]:
    cache.start_run()
    report = cache.load_or_build(root, Settings())
    return [(f.location.path, f.location.line, f.code, f.message) for f in report.findings]


def test_modules_are_grouped_by_what_they_import(root: Path) -> None:
    groups = Program(load_workspace(root).modules).components()
    assert [g for g in groups if len(g) > 1] == [
        ("nav", "nav.monitor", "nav.topics"),
        ("sensors", "sensors.base", "sensors.contacts", "sensors.lidar_driver"),
    ]  # a package's __init__ runs when its modules are imported: it joins their group
    assert ("robot.launch",) in groups  # the launch file imports no workspace module


def test_an_edit_reanalyses_its_group_only_and_the_finding_follows(root: Path, analysed) -> None:
    assert _report(root) == []  # every topic has both ends
    assert len(analysed) == len(Program(load_workspace(root).modules).components())
    analysed.clear()

    topics = root / "nav/nav/topics.py"
    topics.write_text(topics.read_text().replace("SCAN_TOPIC = '/scan'", "SCAN_TOPIC = '/scna'"))
    found = _report(root)
    assert analysed == [("nav", "nav.monitor", "nav.topics")]
    assert [(path, line, code) for path, line, code, _ in found] == [
        ("nav/nav/monitor.py", 12, "ROS003"), ("sensors/sensors/base.py", 7, "ROS001")]
    assert "did you mean '/scan'" in found[0][3] and "did you mean '/scna'" in found[1][3]

    analysed.clear()
    topics.write_text(topics.read_text().replace("'/scna'", "'/scan'"))
    assert _report(root) == []
    assert analysed == []  # that state's groups are still in the cache


def test_kept_groups_give_the_report_of_a_cold_run(root: Path, analysed) -> None:
    _report(root)
    driver = root / "sensors/sensors/lidar_driver.py"
    driver.write_text(driver.read_text().replace("'/scan'", "'/scan_front'"))
    warm = cache.load_or_build(root, Settings())
    assert len(analysed) > 1 and analysed[-1] == ("sensors", "sensors.base", "sensors.contacts",
                                                 "sensors.lidar_driver")
    cold = cache.build_report(root, Settings())
    assert warm.findings == cold.findings and warm.diagnostics == cold.diagnostics
    assert [(f.location.path, f.code) for f in cold.findings] == [("nav/nav/monitor.py", "ROS003")]


@pytest.mark.parametrize("damage", ["garbage", "foreign"])
def test_a_damaged_or_foreign_group_entry_is_analysed_again(root: Path, analysed, damage: str) -> None:
    _report(root)
    entries = sorted((root / cache.CACHE_DIR_NAME / facts_cache.GROUPS_DIR).glob("*.json"))
    assert entries
    for entry in entries:
        if damage == "garbage":
            entry.write_text("{not json")
        else:
            obj = json.loads(entry.read_text())
            obj["signature"] = "0" * 64
            entry.write_text(json.dumps(obj))
    (root / "nav/nav/monitor.py").write_text((root / "nav/nav/monitor.py").read_text() + "\n# edited\n")
    analysed.clear()
    assert _report(root) == []
    assert len(analysed) == len(entries)


def test_an_internal_error_in_one_group_costs_that_group_only(root: Path, monkeypatch) -> None:
    import flake8_rosgraph.analysis as analysis_module
    original = analysis_module.facts_of

    def failing(analysis: Analysis, executables):
        if "nav.monitor" in analysis.program.modules:
            raise RuntimeError("boom")
        return original(analysis, executables)

    monkeypatch.setattr(analysis_module, "facts_of", failing)
    graph = analysis_module.build_graph(root)
    assert {n.name for n in graph.nodes} == {"contact_driver", "lidar_driver"}
    errors = [d for d in graph.diagnostics if d.severity == "error"]
    assert len(errors) == 1 and errors[0].path == "nav/nav/__init__.py"
    assert "not analysed: internal error: RuntimeError: boom" in errors[0].message


def test_unsaved_buffers_read_kept_groups_and_store_none(root: Path, analysed) -> None:
    _report(root)
    folder = root / cache.CACHE_DIR_NAME / facts_cache.GROUPS_DIR
    before = sorted(p.name for p in folder.iterdir())
    analysed.clear()
    monitor = root / "nav/nav/monitor.py"
    buffer = monitor.read_text().replace("SCAN_TOPIC, self.on_scan", "'/scna', self.on_scan").encode()
    cache.start_run()
    report = cache.workspace_report(root, Settings(), ((str(monitor), buffer),))
    assert [(f.location.path, f.code) for f in report.findings] == [
        ("nav/nav/monitor.py", "ROS003"), ("sensors/sensors/base.py", "ROS001")]
    assert analysed == [("nav", "nav.monitor", "nav.topics")]
    assert sorted(p.name for p in folder.iterdir()) == before


def test_the_facts_of_each_group_survive_the_json_round_trip(root: Path, monkeypatch) -> None:
    import flake8_rosgraph.analysis as analysis_module
    seen = []
    original = analysis_module.facts_of
    monkeypatch.setattr(analysis_module, "facts_of",
                        lambda analysis, exes: seen.append(original(analysis, exes)) or seen[-1])
    analysis_module.build_graph(root)
    assert any(facts.nodes for facts in seen) and any(facts.launches for facts in seen)
    for facts in seen:
        assert facts_json.from_obj(json.loads(json.dumps(facts_json.to_obj(facts)))) == facts


def test_what_the_format_cannot_hold_is_refused() -> None:
    with pytest.raises(facts_json.NotAFact):
        facts_json.to_obj(object())
    with pytest.raises(facts_json.NotAFact):
        facts_json.from_obj({"n": "1e999"})
    assert facts_json.from_obj(json.loads(json.dumps(facts_json.to_obj((float("inf"), -float("inf")))))) \
        == (float("inf"), -float("inf"))  # a period of "never", a QoS duration of infinity
    with pytest.raises(facts_json.NotAFact):
        facts_json.from_obj({"c": "os.system", "v": ["true"]})
    with pytest.raises(facts_json.NotAFact):
        facts_json.from_obj({"c": "graph.model.Location", "v": ["a.py", 1]})


def test_metadata_is_read_again_only_when_a_metadata_file_changes(root: Path, monkeypatch) -> None:
    import flake8_rosgraph.analysis as analysis_module
    reads = []
    original = analysis_module.read_metadata
    monkeypatch.setattr(analysis_module, "read_metadata", lambda at: reads.append(at) or original(at))
    assert _report(root) == [] and len(reads) == 1

    monitor = root / "nav/nav/monitor.py"
    monitor.write_text(monitor.read_text() + "\n# a Python edit\n")
    assert _report(root) == [] and len(reads) == 1  # packages, registrations, launch files kept

    setup = root / "sensors/setup.py"  # metadata, though Python: its executables
    setup.write_text(setup.read_text().replace("'lidar_driver = ", "'lidar_node = "))
    found = _report(root)
    assert len(reads) == 2
    assert [(path, line, code) for path, line, code, _ in found] == [("bringup/launch/robot.launch.py", 7, "ROS201")]
    assert "lidar_node" in found[0][3]


def test_an_edit_to_a_script_without_suffix_is_seen(root: Path) -> None:
    """ROS packages install extension-less Python programs (a shebang): the cache must key on them."""
    write(root, {"nav/scripts/scan_logger": """
        #!/usr/bin/env python3
        import rclpy
        from sensor_msgs.msg import LaserScan

        rclpy.init()
        node = rclpy.create_node('scan_logger')
        node.create_subscription(LaserScan, '/scan', print, 10)
        rclpy.spin(node)
    """})
    assert _report(root) == []
    script = root / "nav/scripts/scan_logger"
    script.write_text(script.read_text().replace("'/scan'", "'/scna'"))
    assert [(path, code) for path, _, code, _ in _report(root)] == [("nav/scripts/scan_logger", "ROS003")]


def test_only_the_groups_analysed_again_are_read_and_parsed(root: Path, monkeypatch) -> None:
    import flake8_rosgraph.workspace as workspace_module
    _report(root)
    read = []
    original = workspace_module.read_module
    monkeypatch.setattr(workspace_module, "read_module",
                        lambda path, *args, **kwargs: read.append(path) or original(path, *args, **kwargs))
    topics = root / "nav/nav/topics.py"
    topics.write_text(topics.read_text().replace("SCAN_TOPIC = '/scan'", "SCAN_TOPIC = '/scna'"))
    assert [code for _, _, code, _ in _report(root)] == ["ROS003", "ROS001"]
    # the edited module, and the one of its group the analysis reads (the empty __init__ it never needs)
    assert sorted(p.relative_to(root).as_posix() for p in read) == ["nav/nav/monitor.py", "nav/nav/topics.py"]

    (root / cache.CACHE_DIR_NAME / cache.OUTLINES).write_text('{"files": {}, "signature": "0"}')
    read.clear()
    topics.write_text(topics.read_text().replace("'/scna'", "'/scan'") + "# back\n")
    assert _report(root) == []  # a foreign outline index: every file is read again, nothing lost
    assert len(read) == len(list(root.rglob("*.py")))


def test_every_group_of_a_fleet_workspace_can_be_kept(tmp_path: Path, monkeypatch) -> None:
    """A group whose facts the format cannot hold is analysed again on every run, silently slow:
    the synthetic fleet (timers that never fire, QoS durations of infinity) and examples/ must
    be keepable whole."""
    import sys
    import flake8_rosgraph.analysis as analysis_module
    sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "benchmarks"))
    import synth
    synth.write_workspace(tmp_path / "fleet", 1)
    refused = []
    original = analysis_module.facts_of

    def checked(analysis, executables):
        facts = original(analysis, executables)
        try:
            facts_json.to_obj(facts)
        except facts_json.NotAFact as exc:
            refused.append((min(analysis.program.modules), str(exc)))
        return facts

    monkeypatch.setattr(analysis_module, "facts_of", checked)
    for root in (tmp_path / "fleet", Path(__file__).resolve().parent.parent / "examples"):
        analysis_module.build_graph(root)
    assert refused == []
