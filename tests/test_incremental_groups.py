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
            entry.write_text("0" * 64 + "\n" + entry.read_text().split("\n", 1)[1])
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
        entry = json.dumps({"key": "k", "facts": facts_json.to_obj(facts)})
        assert facts_json.loads_entry(entry) == {"key": "k", "facts": facts}


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


@pytest.mark.parametrize("facts", [
    '{"c": "os.system", "v": ["true"]}',               # not a fact class
    '{"c": "graph.model.Location", "v": ["a.py", 1]}',  # a value missing
    '{"n": "1e999"}', '{"f": [[1]]}', '{"m": [[[1], 2]]}', '{"m": [[1]]}',
    '{"t": [{"shell": "rm -rf /"}]}',                  # an untagged object inside
])
def test_an_entry_whose_facts_the_format_cannot_hold_is_refused(facts: str) -> None:
    with pytest.raises(facts_json.NotAFact):
        facts_json.loads_entry(f'{{"key": "k", "facts": {facts}}}')
    with pytest.raises(facts_json.NotAFact):
        facts_json.from_obj(json.loads(facts))


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


def _files_read_after_misspelling_the_scan_topic(root: Path, monkeypatch) -> list[Path]:
    """After a cold run, misspell the scan topic in ``nav/topics.py`` and report again (the
    finding follows): the files read and parsed on the way, as the list the spy keeps filling."""
    import flake8_rosgraph.workspace as workspace_module
    _report(root)
    read: list[Path] = []
    original = workspace_module.read_module
    monkeypatch.setattr(workspace_module, "read_module",
                        lambda path, *args, **kwargs: read.append(path) or original(path, *args, **kwargs))
    topics = root / "nav/nav/topics.py"
    topics.write_text(topics.read_text().replace("SCAN_TOPIC = '/scan'", "SCAN_TOPIC = '/scna'"))
    assert [code for _, _, code, _ in _report(root)] == ["ROS003", "ROS001"]
    return read


def test_only_the_groups_analysed_again_are_read_and_parsed(root: Path, monkeypatch) -> None:
    read = _files_read_after_misspelling_the_scan_topic(root, monkeypatch)
    topics = root / "nav/nav/topics.py"
    # the edited module, and the one of its group the analysis reads (the empty __init__ it never needs)
    assert sorted(p.relative_to(root).as_posix() for p in read) == ["nav/nav/monitor.py", "nav/nav/topics.py"]

    (root / cache.CACHE_DIR_NAME / cache.OUTLINES).write_text("0" * 64 + '\n{"files": {}}')
    read.clear()
    topics.write_text(topics.read_text().replace("'/scna'", "'/scan'") + "# back\n")
    assert _report(root) == []  # a foreign outline index: every file is read again, nothing lost
    assert len(read) == len(list(root.rglob("*.py")))


def test_a_bare_import_of_a_workspace_file_name_parses_no_kept_module(tmp_path: Path, monkeypatch) -> None:
    """``import monitor`` in a kept module names a workspace file without resolving to it (no
    ``sys.path`` edit there): whether the module edits ``sys.path`` comes from its outline, so
    an edit elsewhere still reads and parses the edited group only."""
    probe = {"sensors/sensors/probe.py": "import rclpy\nimport monitor\n\n\ndef main():\n"
                                         "    rclpy.init()\n    monitor.main()\n"}
    root = write(tmp_path / "ws", {**SENSORS, **NAV, **BRINGUP, **probe})
    read = _files_read_after_misspelling_the_scan_topic(root, monkeypatch)
    assert sorted(p.relative_to(root).as_posix() for p in read) == ["nav/nav/monitor.py", "nav/nav/topics.py"]


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


# -- declarative modules: copied into each importing group, never welding groups together -------

FLEET_INTERFACES = {
    "fleet_interfaces/package.xml": NAV["nav/package.xml"].replace("nav", "fleet_interfaces"),
    # a message package's re-exports, as rosidl generates them (and some repositories commit)
    "fleet_interfaces/msg/__init__.py": """
        from fleet_interfaces.msg._robot_state import RobotState  # noqa: F401
        from fleet_interfaces.msg._task import Task  # noqa: F401
    """,
}
FLEET = package("nav", {
    # topic names in one place, read by the nodes below
    "names": """
        \"\"\"Topics of the fleet.\"\"\"
        STATE_TOPIC = '/fleet/state'
        TASK_TOPICS = ('/fleet/task', '/fleet/task_retry')
        __all__ = ['STATE_TOPIC', 'TASK_TOPICS']
    """,
    "reporter": """
        import rclpy
        from rclpy.node import Node
        from fleet_interfaces.msg import RobotState

        from nav.names import STATE_TOPIC


        class Reporter(Node):
            def __init__(self):
                super().__init__('state_reporter')
                self.state = self.create_publisher(RobotState, STATE_TOPIC, 10)


        def main():
            rclpy.init()
            rclpy.spin(Reporter())
    """,
    "dispatcher": """
        import rclpy
        from rclpy.node import Node
        from fleet_interfaces.msg import RobotState, Task

        from nav import names


        class Dispatcher(Node):
            def __init__(self):
                super().__init__('dispatcher')
                self.create_subscription(RobotState, names.STATE_TOPIC, self.on_state, 10)
                self.tasks = [self.create_publisher(Task, topic, 10) for topic in names.TASK_TOPICS]

            def on_state(self, msg):
                pass


        def main():
            rclpy.init()
            rclpy.spin(Dispatcher())
    """,
    "task_logger": """
        import rclpy
        from rclpy.node import Node
        from fleet_interfaces.msg import Task

        from nav.names import TASK_TOPICS


        class TaskLogger(Node):
            def __init__(self):
                super().__init__('task_logger')
                for topic in TASK_TOPICS:
                    self.create_subscription(Task, topic, self.on_task, 10)

            def on_task(self, msg):
                pass


        def main():
            rclpy.init()
            rclpy.spin(TaskLogger())
    """,
}, {"state_reporter": "reporter", "dispatcher": "dispatcher", "task_logger": "task_logger"})


@pytest.fixture
def fleet(tmp_path: Path) -> Path:
    return write(tmp_path / "ws", {**FLEET_INTERFACES, **FLEET})


def _groups(root: Path) -> list[tuple[str, ...]]:
    return [g for g in Program(load_workspace(root).modules).components() if g != ("setup",)]


def test_declarative_modules_are_copied_into_each_group_that_imports_them(fleet: Path) -> None:
    shared = ("msg", "nav", "nav.names")  # re-exports, an empty __init__, constants
    assert _groups(fleet) == [tuple(sorted((*shared, own))) for own in
                              ("nav.dispatcher", "nav.reporter", "nav.task_logger")]


def test_an_edit_to_one_node_reanalyses_that_node_only(fleet: Path, analysed) -> None:
    assert _report(fleet) == []
    analysed.clear()
    logger = fleet / "nav/nav/task_logger.py"
    logger.write_text(logger.read_text().replace(
        "        for topic in TASK_TOPICS:",
        "        self.retries = self.create_subscription(Task, '/fleet/task_rerty', self.on_task, 10)\n"
        "        for topic in TASK_TOPICS:"))
    found = _report(fleet)
    assert analysed == [("msg", "nav", "nav.names", "nav.task_logger")]
    assert [(path, code) for path, _, code, _ in found] == [("nav/nav/task_logger.py", "ROS003")]
    assert "did you mean '/fleet/task_retry'" in found[0][3]


def test_an_edit_to_a_declarative_module_reanalyses_every_group_that_copies_it(fleet: Path, analysed) -> None:
    _report(fleet)
    analysed.clear()
    names = fleet / "nav/nav/names.py"
    names.write_text(names.read_text().replace("'/fleet/task_retry'", "'/fleet/task_retyr'"))
    assert [code for _, _, code, _ in _report(fleet)] == []  # both ends moved together
    assert analysed == [g for g in _groups(fleet) if "nav.names" in g and len(g) > 3]


def test_a_module_whose_names_others_assign_is_not_copied(fleet: Path, monkeypatch) -> None:
    """``names.STATE_TOPIC = …`` in one module changes what every importer reads: one group,
    analysed as the whole program would be."""
    reporter = fleet / "nav/nav/reporter.py"
    reporter.write_text(reporter.read_text().replace(
        "from nav.names import STATE_TOPIC\n",
        "from nav import names\nfrom nav.names import STATE_TOPIC\n\nnames.STATE_TOPIC = '/fleet/state2'\n"))
    groups = _groups(fleet)
    assert ("msg", "nav", "nav.dispatcher", "nav.names", "nav.reporter", "nav.task_logger") in groups
    grouped = cache.build_report(fleet, Settings())
    monkeypatch.setattr(Program, "components", lambda self: [tuple(sorted(self.modules))])
    whole = cache.build_report(fleet, Settings())
    assert grouped == whole


@pytest.mark.parametrize("source, declares", [
    ('"""Doc."""\nfrom a import b as c\nimport x.y\nN = 3\nT: tuple = ("a", ("b", 1.0))\n', ("N", "T", "c", "x")),
    ("", ()),
    ("from a import *\n", None),             # binds names nobody here can list
    ("N = make()\n", None),                   # runs code
    ("def f():\n    pass\n", None),          # defines code importers call
    ("if DEBUG:\n    N = 1\n", None),
    ("a.b = 1\n", None),
])
def test_declared_names(source: str, declares) -> None:
    import ast
    from flake8_rosgraph.absint.outline import declared_names
    assert declared_names(ast.parse(source)) == declares


def test_attribute_stores_cover_every_assignment_form() -> None:
    import ast
    from flake8_rosgraph.absint.outline import attribute_stores
    source = """
a.one = 1
a.two, [b.three, *c.four] = 2, [3, 4]
a.five += 1
a.six: int = 6
del a.seven
for a.eight in range(3):
    pass
with open(p) as a.nine:
    pass
def f(node):
    node.ten = 10
x = a.read
setattr(a, 'eleven', 11)
"""
    tree = ast.parse(source)
    stored = {"one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten"}
    assert attribute_stores(tree, mentions_setattr=False) == stored
    assert attribute_stores(tree, mentions_setattr=True) == stored | {"eleven"}


#: A package of the workspace's own messages, and a node filling one of them.
MSGS = {
    "robot_msgs/package.xml": NAV["nav/package.xml"].replace("nav", "robot_msgs").replace("ament_python", "ament_cmake"),
    "robot_msgs/msg/Battery.msg": "float32 voltage\nfloat32 percentage\n",
}
REPORTER = package("power", {
    "reporter": """
        import rclpy
        from rclpy.node import Node
        from robot_msgs.msg import Battery


        class Reporter(Node):
            def __init__(self):
                super().__init__('battery_reporter')
                self.out = self.create_publisher(Battery, '/battery', 10)
                self.create_timer(1.0, self.tick)

            def tick(self):
                msg = Battery()
                msg.voltage = 12.1
                msg.current = 0.4
                self.out.publish(msg)


        def main():
            rclpy.init()
            rclpy.spin(Reporter())
    """,
}, {"battery_reporter": "reporter"})


def test_the_workspaces_own_messages_are_kept_with_its_metadata(tmp_path: Path, monkeypatch) -> None:
    """Its message files are read with the other metadata, once: a Python edit reads none of
    them again, and an edit of a message file is seen."""
    from flake8_rosgraph import metadata

    root = write(tmp_path / "ws", {**MSGS, **REPORTER})
    field_finding = [("power/power/reporter.py", 15, "ROS107")]
    assert [(p, line, code) for p, line, code, _ in _report(root)] == field_finding  # no field 'current'

    walked: list[Path] = []
    original = metadata.interface_files
    monkeypatch.setattr(metadata, "interface_files", lambda folder, *a: walked.append(folder) or original(folder, *a))

    reporter = root / "power/power/reporter.py"
    reporter.write_text(reporter.read_text().replace("12.1", "12.2"))
    assert [(p, line, code) for p, line, code, _ in _report(root)] == field_finding
    assert walked == []  # the metadata, message files included, came from the cache

    (root / "robot_msgs/msg/Battery.msg").write_text("float32 voltage\nfloat32 current\nfloat32 percentage\n")
    assert _report(root) == []
    assert walked == [root]
