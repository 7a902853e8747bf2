"""A branch rules constants out of a local (``absint/exclusion.py``): a fleet bridge that loops
over robot namespaces, one of them the empty root namespace, builds ``'/' + ns + '/cmd_vel'``
only where ``ns`` is not empty, so no ``'//cmd_vel'`` is extracted (nor reported as an invalid
name, ROS006); the same for ``if ns:`` (also ``if self.ns:`` right after storing it),
``x is not None``, ``x not in (...)``, ``not x`` and ``a and b``, and in the branches of
``a if test else b`` (also in a comprehension); ``isinstance(result, String)`` tells message
objects apart. A loop over a written-out table evaluates a creation call once per row that
reaches it: ``if not enabled: continue`` skips the disabled rows, and the others keep their
own types. Twins: a comparison with a value the run may replace rules nothing out, and a
loop over a table keeps its rows where no test narrows the loop variable."""
from __future__ import annotations

from pathlib import Path

from test_recall_globals_and_escapes import package
from test_recall_mechanisms import entities
from test_recall_scopes_and_reasons import reasons
from test_workspace_discovery import write

from flake8_rosgraph.analysis import build_graph
from flake8_rosgraph.cache import build_report
from flake8_rosgraph.options import Settings

TOPICS = ("publishers", "subscriptions")

FLEET = """
    # The robots the bridge serves; '' is the robot that runs in the root namespace.
    ROBOTS = ['', 'turtle1', 'turtle2']
    CAMERAS = ('front', None, 'rear')
"""
BRIDGE = """
    import rclpy
    from geometry_msgs.msg import Pose, Twist
    from rclpy.node import Node
    from sensor_msgs.msg import Image

    from fleet_bridge import fleet


    class FleetBridge(Node):
        def __init__(self):
            super().__init__('fleet_bridge')
            self.cmd = {}
            for robot in fleet.ROBOTS:
                if robot == '':
                    self.cmd[robot] = self.create_publisher(Twist, '/cmd_vel', 10)
                else:
                    self.cmd[robot] = self.create_publisher(Twist, '/' + robot + '/cmd_vel', 10)
                if robot:
                    self.create_subscription(Pose, f'/{robot}/pose', self.on_pose, 10)
            odometry = ['/' + robot + '/odom' if robot else '/odom' for robot in fleet.ROBOTS]
            for topic in odometry:
                self.create_subscription(Pose, topic, self.on_pose, 10)
            for camera in fleet.CAMERAS:
                if camera is not None and camera not in ('rear',):
                    self.create_subscription(Image, f'/{camera}/image_raw', self.on_image, 10)

        def on_pose(self, msg):
            self.get_logger().info(str(msg.position.x))

        def on_image(self, msg):
            self.get_logger().info(str(msg.width))


    def main():
        rclpy.init()
        rclpy.spin(FleetBridge())
"""
TELEOP = """
    import rclpy
    from geometry_msgs.msg import Twist
    from rclpy.node import Node


    class Teleop(Node):
        '''Drives one robot, or the one in the root namespace when no prefix is set.'''

        def __init__(self):
            super().__init__('teleop')
            prefix = self.declare_parameter('prefix', '').value
            if not prefix:
                self.pub = self.create_publisher(Twist, '/cmd_vel', 10)
            else:
                self.pub = self.create_publisher(Twist, '/' + prefix + '/cmd_vel', 10)


    class Relay(Node):
        '''Relays commands into the robot's namespace, or the root one when none is set.'''

        def __init__(self):
            super().__init__('relay')
            self.robot_ns = self.declare_parameter('robot_ns', '').value
            if self.robot_ns:
                self.out = self.create_publisher(Twist, '/' + self.robot_ns + '/cmd_vel_out', 10)
            else:
                self.out = self.create_publisher(Twist, '/cmd_vel_out', 10)


    def main():
        rclpy.init()
        rclpy.spin(Teleop())


    def relay():
        rclpy.init()
        rclpy.spin(Relay())
"""


def _workspace(tmp_path: Path, bridge: str = BRIDGE) -> Path:
    return write(tmp_path, package("fleet_bridge", "'bridge = fleet_bridge.bridge:main', "
                                                   "'teleop = fleet_bridge.teleop:main', "
                                                   "'relay = fleet_bridge.teleop:relay'",
                                   {"fleet": FLEET, "bridge": bridge, "teleop": TELEOP}))


def test_a_branch_builds_names_only_from_the_constants_it_lets_through(tmp_path: Path) -> None:
    root = _workspace(tmp_path)
    assert entities(root, TOPICS) == {
        "/fleet_bridge": [("publishers", "/cmd_vel"), ("publishers", "/turtle1/cmd_vel"),
                          ("publishers", "/turtle2/cmd_vel"), ("subscriptions", "/front/image_raw"),
                          ("subscriptions", "/odom"), ("subscriptions", "/turtle1/odom"),
                          ("subscriptions", "/turtle1/pose"), ("subscriptions", "/turtle2/odom"),
                          ("subscriptions", "/turtle2/pose")],
        # the prefixed publisher is made only for a prefix the run sets: its name is unknown
        "/teleop": [("publishers", "/cmd_vel"), ("publishers", "?")],
        # the same with the prefix kept on the node: an attribute it just stored
        "/relay": [("publishers", "/cmd_vel_out"), ("publishers", "?")],
    }


def test_explain_says_the_default_does_not_reach_the_prefixed_name(tmp_path: Path) -> None:
    root = _workspace(tmp_path)
    status, why = reasons(root)[("fleet_bridge/fleet_bridge/teleop.py", 15)]
    assert status == "unknown" and any(reason.startswith(
        "it is built from ROS parameter 'prefix' of its node, with no default in code that reaches this call")
        for reason in why)


def test_no_name_the_code_never_makes_is_reported_invalid(tmp_path: Path) -> None:
    root = _workspace(tmp_path)
    report = build_report(root, Settings())
    assert [f for f in report.findings if f.code == "ROS006"] == []


def test_a_comparison_with_a_value_the_run_may_replace_rules_nothing_out(tmp_path: Path) -> None:
    """The twin: ``robot == default_robot`` where the default comes from a parameter: the run
    may compare with another name, so every robot keeps every branch."""
    bridge = BRIDGE.replace(
        "            for robot in fleet.ROBOTS:\n                if robot == '':",
        "            default_robot = self.declare_parameter('default_robot', 'turtle1').value\n"
        "            for robot in fleet.ROBOTS:\n                if robot == default_robot:")
    root = _workspace(tmp_path, bridge)
    publishers = entities(root, ("publishers",))["/fleet_bridge"]
    assert ("publishers", "/turtle1/cmd_vel") in publishers and ("publishers", "/cmd_vel") in publishers


def test_a_table_loop_without_a_test_on_its_variables_keeps_each_row(tmp_path: Path) -> None:
    """The twin: the rows of a written-out table still pair each name with its own type when a
    test in the loop narrows another local."""
    bridge = """
        import rclpy
        from geometry_msgs.msg import Twist
        from rclpy.node import Node
        from std_msgs.msg import String

        STREAMS = [('/status', String), ('/cmd_vel', Twist)]


        class Streams(Node):
            def __init__(self, mode=''):
                super().__init__('streams')
                for topic, kind in STREAMS:
                    if mode:
                        self.get_logger().info(mode)
                    self.create_publisher(kind, topic, 10)


        def main():
            rclpy.init()
            rclpy.spin(Streams())
    """
    root = _workspace(tmp_path, bridge)
    graph = build_graph(root)
    streams = next(n for n in graph.nodes if n.fqn == "/streams")
    assert sorted((e.name, e.type) for e in streams.entities) == [
        ("/cmd_vel", "geometry_msgs/msg/Twist"), ("/status", "std_msgs/msg/String")]


def test_a_table_loop_creates_only_the_rows_a_branch_lets_through(tmp_path: Path) -> None:
    """``SENSORS`` lists a disabled stream: the loop skips it with ``continue`` (or creates
    the others under ``if enabled and name is not None:``); each enabled row keeps its type."""
    sensors = """
        import rclpy
        from geometry_msgs.msg import Twist
        from rclpy.node import Node
        from sensor_msgs.msg import Imu
        from std_msgs.msg import String

        SENSORS = [('/imu', Imu, True), ('/status', String, False), ('/cmd_vel', Twist, True),
                   (None, String, True)]


        class Streams(Node):
            def __init__(self):
                super().__init__('streams')
                for name, kind, enabled in SENSORS:
                    if not enabled or name is None:
                        continue
                    self.create_subscription(kind, name, self.on_message, 10)
                for name, kind, enabled in SENSORS:
                    if enabled and name is not None:
                        self.create_publisher(kind, name + '/echo', 10)

            def on_message(self, msg):
                self.get_logger().info(str(msg))


        def main():
            rclpy.init()
            rclpy.spin(Streams())
    """
    root = _workspace(tmp_path, sensors)
    streams = next(n for n in build_graph(root).nodes if n.fqn == "/streams")
    assert sorted((e.kind, e.name, e.type) for e in streams.entities) == [
        ("publishers", "/cmd_vel/echo", "geometry_msgs/msg/Twist"),
        ("publishers", "/imu/echo", "sensor_msgs/msg/Imu"),
        ("subscriptions", "/cmd_vel", "geometry_msgs/msg/Twist"),
        ("subscriptions", "/imu", "sensor_msgs/msg/Imu")]


def test_a_table_loop_skips_the_rows_an_ordering_rules_out(tmp_path: Path) -> None:
    """A rate table where 0 Hz means "off": ``if hz <= 0: continue`` (or ``0 < hz`` read from
    the other side) creates only the running streams' publishers and timers. The twin:
    ``hz >= 0`` lets the 0 Hz row through, and its timer period is reported (ROS106)."""
    rates = """
        import rclpy
        from rclpy.node import Node
        from sensor_msgs.msg import Imu, NavSatFix
        from std_msgs.msg import String

        RATES = [('/imu', Imu, 100.0), ('/gps', NavSatFix, 0.0), ('/status', String, 1)]


        class Streams(Node):
            def __init__(self):
                super().__init__('streams')
                for name, kind, hz in RATES:
                    if hz <= 0:
                        continue
                    self.create_publisher(kind, name, 10)
                for name, kind, hz in RATES:
                    if 0 < hz:
                        self.create_timer(1.0 / hz, self.tick)
                        self.create_publisher(kind, name + '/rate', 10)

            def tick(self):
                pass


        def main():
            rclpy.init()
            rclpy.spin(Streams())
    """
    root = _workspace(tmp_path, rates)
    streams = next(n for n in build_graph(root).nodes if n.fqn == "/streams")
    assert sorted((e.kind, e.name) for e in streams.entities if e.kind == "publishers") == [
        ("publishers", "/imu"), ("publishers", "/imu/rate"),
        ("publishers", "/status"), ("publishers", "/status/rate")]
    report = build_report(root, Settings())
    assert not [f for f in report.findings if f.code == "ROS106"]

    root = _workspace(tmp_path / "twin", rates.replace("if 0 < hz:", "if hz >= 0:")
                      .replace("self.create_timer(1.0 / hz, self.tick)", "self.create_timer(hz, self.tick)"))
    report = build_report(root, Settings())
    assert [(f.code, f.location.line) for f in report.findings if f.code == "ROS106"] == [("ROS106", 18)]


RESULTS = """
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import Int32, String


    class ResultRelay(Node):
        '''Publishes each result on the topic of its type.'''

        def __init__(self):
            super().__init__('result_relay')
            self.text_out = self.create_publisher(String, '/results/text', 10)
            self.count_out = self.create_publisher(Int32, '/results/count', 10)
            self.create_timer(1.0, self.on_timer)

        def on_timer(self):
            for result in (String(data='done'), Int32(data=3)):
                self.forward(result)

        def forward(self, result):
            if isinstance(result, String):
                self.text_out.publish(result)
            else:
                self.count_out.publish(result)
            if not isinstance(result, (String, Int32)):
                self.text_out.publish(result)


    def main():
        rclpy.init()
        rclpy.spin(ResultRelay())
"""


def _relay(tmp_path: Path, relay: str) -> list[tuple[int, str]]:
    root = write(tmp_path, package("result_relay", "'relay = result_relay.relay:main'", {"relay": relay}))
    report = build_report(root, Settings())
    return sorted((f.location.line, f.code) for f in report.findings if f.code == "ROS104")


def test_a_type_test_tells_message_objects_apart(tmp_path: Path) -> None:
    """``isinstance(result, String)`` takes the text result one way and the count the other
    (generated message classes derive from ``object`` alone): neither publisher is handed the
    other type (ROS104), and the branch no type reaches publishes nothing."""
    assert _relay(tmp_path, RESULTS) == []


def test_a_type_test_on_the_wrong_class_still_reports_the_mismatch(tmp_path: Path) -> None:
    """The twin: dispatching on the wrong class publishes each result on the other's topic."""
    assert _relay(tmp_path, RESULTS.replace("if isinstance(result, String):", "if isinstance(result, Int32):")) \
        == [(21, "ROS104"), (23, "ROS104")]
