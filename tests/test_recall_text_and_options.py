"""Extraction mechanisms found on an eighth round of real repositories outside every test set:
text built from a value that is one of a few known strings *or* unknown (``sys.argv[1] if
len(sys.argv) > 1 else 'nautilus'``) keeps the known texts, marked as only partly known; a
comparison decided on a command-line option's default is itself only a default, so a
required argument checked with ``if args.side not in (...): raise`` no longer ends the
program; and ``--explain`` says where a module-level name comes from (a global set by a
function, a single non-literal binding) and no longer calls a parameter's missing message
type unknown. Each on a realistic multi-file workspace, with a twin where following the code
must not invent an entity."""
from __future__ import annotations

from pathlib import Path

from test_recall_globals_and_escapes import package
from test_recall_mechanisms import entities
from test_recall_scopes_and_reasons import reasons
from test_workspace_discovery import write

from flake8_rosgraph.analysis import build_graph

TOPICS = ("publishers", "subscriptions", "action_clients")


def _partial(root: Path) -> dict[str | None, list[tuple[str, str, bool]]]:
    """Each node's topics and actions as ``(kind, name or "?", partly known)``."""
    return {node.fqn: sorted((e.kind, e.name or "?", e.partial) for e in node.entities
                             if e.kind in TOPICS)
            for node in build_graph(root).nodes}


# -- text built from a partly known value keeps the known texts -----------------------------
GOAL_CHECK = """
    import sys

    import rclpy
    from geometry_msgs.msg import PoseWithCovarianceStamped
    from rclpy.action import ActionClient
    from rclpy.node import Node

    from sim_checks.actions import Waypoint
    from sim_checks.topics import pose_topic

    {binding}


    class GoalChecker(Node):
        def __init__(self):
            super().__init__('goal_checker')
            self.pose_sub = self.create_subscription(
                PoseWithCovarianceStamped, f'/{{namespace}}/pose', self.on_pose, 1)
            self.odom_sub = self.create_subscription(
                PoseWithCovarianceStamped, pose_topic(namespace, 'odom'), self.on_pose, 1)
            self.goal_client = ActionClient(self, Waypoint, '/%s/waypoint' % namespace)
            self.pose = None

        def on_pose(self, msg):
            self.pose = msg.pose.pose


    def main():
        rclpy.init()
        rclpy.spin(GoalChecker())
"""
TOPIC_HELPERS = """
    def pose_topic(namespace, source):
        '''The pose topic of one estimator under the vehicle's namespace.'''
        return '/{}/{}/pose'.format(namespace, source)
"""
ACTIONS = """
    from vortex_msgs.action import ReferenceFilterWaypoint as Waypoint
"""


def _goal_check(tmp_path: Path, binding: str) -> Path:
    return write(tmp_path, package("sim_checks", "'check_goal = sim_checks.check_goal:main'", {
        "check_goal": GOAL_CHECK.replace("{binding}", binding).replace("{{", "{").replace("}}", "}"),
        "topics": TOPIC_HELPERS, "actions": ACTIONS}))


def test_text_built_from_a_partly_known_value_keeps_the_known_texts(tmp_path: Path) -> None:
    """``namespace`` is the first command-line argument or ``'nautilus'``: the f-string, the
    ``%`` format and ``str.format`` in a helper of another module each keep the default's
    name, marked as only partly known, beside an unknown rest (vortex-auv's simulator
    checks)."""
    root = _goal_check(tmp_path, "namespace = sys.argv[1] if len(sys.argv) > 1 else 'nautilus'")
    assert _partial(root) == {"/goal_checker": [
        ("action_clients", "/nautilus/waypoint", True), ("action_clients", "?", False),
        ("subscriptions", "/nautilus/odom/pose", True), ("subscriptions", "/nautilus/pose", True),
        ("subscriptions", "?", False), ("subscriptions", "?", False)]}
    status, why = reasons(root)[("sim_checks/sim_checks/check_goal.py", 17)]
    assert status == "unknown"
    assert why == ("unknown name (known only partly: '/nautilus/pose' on some paths, unknown "
                   "on others)", "it depends on module-level `namespace = sys.argv[1] if "
                   "len(sys.argv) > 1 else 'nautilus'`, whose value is not known statically")


def test_text_built_from_an_unknown_value_names_nothing(tmp_path: Path) -> None:
    """The twin: a namespace with no fallback (the environment's) leaves each name unknown,
    and no known part of the template is passed off as a name."""
    root = _goal_check(tmp_path, "import os\n    namespace = os.environ['VEHICLE']")
    assert _partial(root) == {"/goal_checker": [
        ("action_clients", "?", False), ("subscriptions", "?", False),
        ("subscriptions", "?", False)]}


def test_a_function_setting_a_global_is_named_as_its_source(tmp_path: Path) -> None:
    """A module constant that a launch-test setup function rebinds through ``global`` is the
    literal or whatever the function computed: ``--explain`` names that function, rather than
    calling the two bindings conditions at module level (vortex-auv's waypoint tests)."""
    root = _goal_check(tmp_path, """namespace = 'orca'


    def use_vehicle(context):
        global namespace
        namespace = context.launch_configurations['namespace']""")
    assert entities(root, ("subscriptions",)) == {"/goal_checker": [
        ("subscriptions", "/orca/odom/pose"), ("subscriptions", "/orca/pose"),
        ("subscriptions", "?"), ("subscriptions", "?")]}
    _, why = reasons(root)[("sim_checks/sim_checks/check_goal.py", 22)]
    assert why[1] == ("`namespace` is also set by function use_vehicle (`global namespace`), "
                       "whose value there is not known statically")


# -- a comparison decided on an option's default is only a default ---------------------------
VIEWER = """
    import argparse

    import rclpy

    from camera_tools.subscriber import CameraSubscriber


    def _arguments():
        parser = argparse.ArgumentParser(description='Show one camera of the head.')
        parser.add_argument('side')
        parser.add_argument('source')
        parser.add_argument('--mode', default=None)
        return parser.parse_args()


    def main():
        args = _arguments()
        side = args.side
        if side not in ['left', 'right']:
            raise ValueError("side must be 'left' or 'right'")
        if args.source not in ('ros', 'opencv'):
            raise ValueError("source must be 'ros' or 'opencv'")
        if args.source == 'ros':
            rclpy.init()
            viewer = CameraSubscriber(node_name='image_viewer', side=side)
            {extra}
            rclpy.spin(viewer)
"""
SUBSCRIBER = """
    from rclpy.node import Node
    from sensor_msgs.msg import CompressedImage
    from std_msgs.msg import String


    class CameraSubscriber(Node):
        '''Keeps the last compressed frame of one camera.'''

        def __init__(self, node_name, side):
            super().__init__(node_name=node_name)
            self.sub = self.create_subscription(
                CompressedImage, side + '_image/image_raw/compressed', self.on_image, 1)
            self.image = None

        def on_image(self, msg):
            self.image = msg.data

        def announce(self, mode):
            self.create_publisher(String, f'viewer/{mode}', 1)
"""


def _viewer(tmp_path: Path, extra: str = "") -> Path:
    return write(tmp_path, package("camera_tools", "'view = camera_tools.view:main'", {
        "view": VIEWER.replace("{extra}", extra), "subscriber": SUBSCRIBER}))


def test_a_required_argument_checked_against_choices_keeps_the_program_going(tmp_path: Path) -> None:
    """argparse keeps ``None`` as the default of ``side``, but a positional argument is
    required: ``None not in [...]`` names what runs by default and must not decide that every
    run raises. The node runs with its name, and the checked side gives its two topics
    (reachy's camera viewer)."""
    root = _viewer(tmp_path)
    assert entities(root, ("subscriptions",)) == {"/image_viewer": [
        ("subscriptions", "/left_image/image_raw/compressed"),
        ("subscriptions", "/right_image/image_raw/compressed")]}


def test_a_branch_on_an_option_default_still_explores_both_ways(tmp_path: Path) -> None:
    """The twin: an option's comparison with a literal decides nothing either way, so the
    publisher made under ``if args.mode == 'sim'`` exists on some paths; the option's unset
    default ``None`` is never formatted into its name (``/viewer/None`` would be a confident
    wrong name): the name is unknown."""
    root = _viewer(tmp_path, "if args.mode == 'sim':\n                viewer.announce(args.mode)")
    assert entities(root, ("publishers",)) == {"/image_viewer": [("publishers", "?")]}


def test_a_literal_comparison_still_decides_the_branch(tmp_path: Path) -> None:
    """Precision: a module literal that is not an option still decides ``not in``: the
    node after the ``raise`` never runs; its class is analysed on its own, with unknown
    arguments, and no name is invented for it."""
    root = write(tmp_path, package("camera_tools", "'view = camera_tools.view:main'", {
        "view": """
            import rclpy

            from camera_tools.subscriber import CameraSubscriber

            SIDE = 'top'


            def main():
                if SIDE not in ('left', 'right'):
                    raise SystemExit('no such camera')
                rclpy.init()
                rclpy.spin(CameraSubscriber('image_viewer', SIDE))
        """, "subscriber": SUBSCRIBER}))
    assert entities(root, ("subscriptions",)) == {None: [("subscriptions", "?")]}


# -- a parameter has no message type ----------------------------------------------------------
DIAGNOSTICS = """
    import rclpy
    from diagnostic_updater import Updater
    from rclpy.node import Node
    from sensor_msgs.msg import BatteryState


    class BaseDiagnostics(Node):
        def __init__(self):
            super().__init__('base_diagnostics')
            self.updater = Updater(self)
            self.updater.setHardwareID('base')
            self.create_subscription(BatteryState, 'battery_state', self.on_battery, 10)
            self.voltage = 0.0

        def on_battery(self, msg):
            self.voltage = msg.voltage


    def main():
        rclpy.init()
        rclpy.spin(BaseDiagnostics())
"""


def test_a_library_call_that_declares_parameters_is_complete(tmp_path: Path) -> None:
    """``Updater(node)`` publishes ``/diagnostics`` and declares two parameters: parameters
    carry no message type, so the site is complete, not "in the graph with unknown type"."""
    root = write(tmp_path, package("base_diag", "'diag = base_diag.diag:main'", {
        "diag": DIAGNOSTICS}))
    assert reasons(root)[("base_diag/base_diag/diag.py", 10)] == ("complete", ())


# -- a library that calls a callback with the arguments it was handed ------------------------
DASHBOARD_SERVER = """
    import threading

    import rclpy
    from flask import Flask
    from flask_socketio import SocketIO

    from robot_dashboard.bridge import relay_commands, stream_status

    ROBOTS = ['red_robot', 'blue_robot']

    app = Flask(__name__)
    socketio = SocketIO(app, async_mode='threading')


    def main():
        rclpy.init()
        node = rclpy.create_node('dashboard')
        for robot in ROBOTS:
            threading.Thread(target=relay_commands, args=(node, robot), daemon=True).start()
        socketio.start_background_task(stream_status, node, {start})
        socketio.run(app, host='127.0.0.1')
"""
DASHBOARD_BRIDGE = """
    from geometry_msgs.msg import Twist
    from std_msgs.msg import String


    def relay_commands(node, robot):
        '''Forwards the browser's velocity commands to one robot.'''
        node.create_publisher(Twist, f'/{robot}/cmd_vel', 10)


    def stream_status(node, robots, period=0.5):
        '''Pushes each robot's status text to the browser.'''
        for robot in robots:
            node.create_subscription(String, f'/{robot}/status', print, 10)
        node.create_timer(period, lambda: None)
"""


def _dashboard(tmp_path: Path, start: str) -> Path:
    return write(tmp_path, package("robot_dashboard", "'server = robot_dashboard.server:main'", {
        "server": DASHBOARD_SERVER.replace("{start}", start), "bridge": DASHBOARD_BRIDGE}))


def test_thread_and_background_task_targets_get_the_arguments_passed_beside_them(tmp_path: Path) -> None:
    """``Thread(target=f, args=(node, robot))`` and Flask-SocketIO's
    ``start_background_task(f, node, robots)`` call ``f`` with those arguments: the node the
    server made and each robot's name, so every entity is on ``/dashboard`` with its name
    (a referee web dashboard's ROS thread, 5 sites "not in the graph" before)."""
    root = _dashboard(tmp_path, "ROBOTS, period=1.0")
    assert entities(root, ("publishers", "subscriptions")) == {"/dashboard": [
        ("publishers", "/blue_robot/cmd_vel"), ("publishers", "/red_robot/cmd_vel"),
        ("subscriptions", "/blue_robot/status"), ("subscriptions", "/red_robot/status")]}
    (node,) = build_graph(root).nodes
    assert [t.period for t in node.entities if t.kind == "timers"] == [1.0]


def test_a_target_called_with_what_the_analysis_cannot_list_invents_nothing(tmp_path: Path) -> None:
    """The twin: arguments unpacked from a list the analysis does not know (``*robots_of()``)
    leave the target's parameters unknown: it is still analysed, but creates on no known
    node, and no robot name is guessed."""
    root = _dashboard(tmp_path, "*__import__('json').loads(open('robots.json').read())")
    got = entities(root, ("publishers", "subscriptions"))
    assert got == {"/dashboard": [("publishers", "/blue_robot/cmd_vel"),
                                  ("publishers", "/red_robot/cmd_vel")]}


# -- text normalised from a parameter's default is still only a default ----------------------
NAVIGATOR = """
    import rclpy
    from geometry_msgs.msg import PoseWithCovarianceStamped
    from nav_msgs.msg import Odometry
    from rclpy.node import Node

    from nav_bridge.settings import {source}


    class NavigationBridge(Node):
        def __init__(self):
            super().__init__('navigation_bridge')
            self.declare_parameter('pose_source', 'amcl')  # 'amcl' | 'odom'
            self.pose_source = {read}
            if self.pose_source == 'odom':
                self.create_subscription(Odometry, 'odom', self.on_odom, 10)
            else:
                self.create_subscription(PoseWithCovarianceStamped, 'amcl_pose', self.on_amcl, 10)

        def on_odom(self, msg):
            self.pose = msg.pose.pose

        def on_amcl(self, msg):
            self.pose = msg.pose.pose


    def main():
        rclpy.init()
        rclpy.spin(NavigationBridge())
"""
SETTINGS = """
    DEFAULT_SOURCE = ' AMCL '


    def normalised(text):
        '''How the bridge compares a source name: trimmed, lower case.'''
        return str(text).strip().lower()
"""


def _navigator(tmp_path: Path, read: str) -> Path:
    return write(tmp_path, package("nav_bridge", "'bridge = nav_bridge.bridge:main'", {
        "bridge": NAVIGATOR.replace("{source}", "DEFAULT_SOURCE, normalised").replace("{read}", read),
        "settings": SETTINGS}))


def test_a_parameter_normalised_by_string_methods_decides_no_branch(tmp_path: Path) -> None:
    """``str(self.get_parameter('pose_source').value).strip().lower()`` in a helper of another
    module is still the parameter's overridable default: ``== 'odom'`` names what runs by
    default but both subscriptions exist in some configuration (an AMR's navigation bridge:
    the odometry one was "never reached")."""
    root = _navigator(tmp_path, "normalised(self.get_parameter('pose_source').value)")
    assert entities(root, ("subscriptions",)) == {"/navigation_bridge": [
        ("subscriptions", "/amcl_pose"), ("subscriptions", "/odom")]}


def test_a_normalised_literal_still_decides_the_branch(tmp_path: Path) -> None:
    """The twin: the same normalisation of a module literal is a plain constant, and the
    branch it decides leaves no odometry subscription."""
    root = _navigator(tmp_path, "normalised(DEFAULT_SOURCE)")
    assert entities(root, ("subscriptions",)) == {"/navigation_bridge": [
        ("subscriptions", "/amcl_pose")]}


# -- a node's fully qualified name builds its own topics -------------------------------------
HEARTBEAT_BASE = """
    from rclpy.node import Node
    from std_msgs.msg import Header


    class HeartbeatNode(Node):
        '''A node that announces itself on <its fully qualified name>/heartbeat.'''

        def __init__(self, name, **kwargs):
            super().__init__(name, **kwargs)
            self.heartbeat = self.create_publisher(
                Header, self.get_fully_qualified_name() + '/heartbeat', 1)
            self.create_timer(1.0, self.beat)

        def beat(self):
            self.heartbeat.publish(Header(frame_id=self.get_name()))
"""
HEARTBEAT_NODES = """
    import sys

    import rclpy
    from rclpy.executors import MultiThreadedExecutor

    from fleet_health.base import HeartbeatNode


    class BatteryMonitor(HeartbeatNode):
        def __init__(self):
            super().__init__('battery_monitor', namespace='robot1')


    class Docking(HeartbeatNode):
        def __init__(self, name):
            super().__init__(name)


    def main():
        rclpy.init()
        executor = MultiThreadedExecutor()
        executor.add_node(BatteryMonitor())
        executor.add_node(Docking({name}))
        executor.spin()
"""


def test_a_nodes_fully_qualified_name_builds_its_topic(tmp_path: Path) -> None:
    """``get_fully_qualified_name()`` is rcl's namespace and name joined (``/robot1/…`` for a
    namespaced node, ``/docking`` in the root namespace), in a base class of another module."""
    root = write(tmp_path, package("fleet_health", "'health = fleet_health.nodes:main'", {
        "base": HEARTBEAT_BASE, "nodes": HEARTBEAT_NODES.replace("{name}", "'docking'")}))
    assert entities(root, ("publishers",)) == {
        "/docking": [("publishers", "/docking/heartbeat")],
        "/robot1/battery_monitor": [("publishers", "/robot1/battery_monitor/heartbeat")]}


def test_an_unknown_node_name_gives_no_fully_qualified_name(tmp_path: Path) -> None:
    """The twin: a node named from the command line has no known fully qualified name, and
    its heartbeat topic stays unknown (its namespace alone names nothing)."""
    root = write(tmp_path, package("fleet_health", "'health = fleet_health.nodes:main'", {
        "base": HEARTBEAT_BASE, "nodes": HEARTBEAT_NODES.replace("{name}", "sys.argv[1]")}))
    assert entities(root, ("publishers",)) == {
        None: [("publishers", "?")],
        "/robot1/battery_monitor": [("publishers", "/robot1/battery_monitor/heartbeat")]}
