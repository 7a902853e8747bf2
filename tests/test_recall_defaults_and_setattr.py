"""Extraction mechanisms found on a seventh round of real repositories outside every test set:
a value chosen by a command-line option's default (``None if args.trace is None else
args.trace.resolve()``) is itself only a default, so a later ``if`` on it explores both
ways; and a configuration object filled by ``setattr`` in a loop over a table of parameter
defaults longer than a value holds keeps each key's own value, while one filled by names the
analysis does not know keeps none of its class defaults for sure. Each on a realistic
multi-file workspace, with a twin where following the code must not invent an entity."""
from __future__ import annotations

from pathlib import Path

from test_recall_globals_and_escapes import package
from test_recall_mechanisms import entities
from test_recall_scopes_and_reasons import reasons
from test_workspace_discovery import write

from flake8_rosgraph.analysis import build_graph

TOPICS = ("publishers", "subscriptions")


# -- a choice made by an option's default is only a default -----------------------------------
SIMULATION = """
    import rclpy
    from geometry_msgs.msg import Twist
    from nav_msgs.msg import Odometry
    from rclpy.node import Node

    from sim_runner.trace import OdomTrace


    def run(world, trace_path=None):
        rclpy.init(args=[])
        node = Node('sim_bridge')
        node.create_subscription(Odometry, '/odom', print, 10)
        if trace_path is not None:
            trace = OdomTrace(trace_path)
            node.create_publisher(Twist, '/cmd_vel', 1)
            node.create_subscription(Odometry, '/odom/ground_truth', trace.record, 10)
        rclpy.spin(node)
"""
TRACE = """
    class OdomTrace:
        '''Writes every odometry message to a file, for the offline phase check.'''

        def __init__(self, path):
            self.path = path

        def record(self, msg):
            with open(self.path, 'a') as out:
                out.write(f'{msg.header.stamp.sec}\\n')
"""
MAIN = """
    import argparse
    from pathlib import Path

    from sim_runner.simulation import run


    def _parser():
        parser = argparse.ArgumentParser(description='Run the simulation bridge')
        parser.add_argument('--world', default='warehouse')
        parser.add_argument('--odom-trace', type=Path, default=None)
        return parser


    def main(argv=None):
        args = _parser().parse_args(argv)
        run(args.world, {trace})
        return 0
"""


def _simulation(tmp_path: Path, trace: str) -> Path:
    return write(tmp_path, package("sim_runner", "'sim = sim_runner.main:main'", {
        "simulation": SIMULATION, "trace": TRACE, "main": MAIN.replace("{trace}", trace)}))


def test_an_option_default_chosen_by_a_conditional_decides_no_later_branch(tmp_path: Path) -> None:
    """``None if args.odom_trace is None else …`` is None only by default: ``--odom-trace``
    given, ``run`` takes the traced branch, so its publisher and subscription are in the
    graph (Isaac Sim navigation bridge: nine sites reported never reached)."""
    root = _simulation(tmp_path, "None if args.odom_trace is None else args.odom_trace.expanduser()")
    assert entities(root, TOPICS) == {"/sim_bridge": [
        ("publishers", "/cmd_vel"), ("subscriptions", "/odom"),
        ("subscriptions", "/odom/ground_truth")]}


def test_an_attribute_of_an_option_default_of_none_is_the_given_value(tmp_path: Path) -> None:
    """``args.odom_trace.expanduser()`` fails on the default ``None`` but not on a path given
    on the command line: the call goes on, with a value the analysis does not know."""
    root = _simulation(tmp_path, "args.odom_trace.expanduser()")
    assert entities(root, TOPICS)["/sim_bridge"] == [
        ("publishers", "/cmd_vel"), ("subscriptions", "/odom"),
        ("subscriptions", "/odom/ground_truth")]


def test_a_conditional_on_a_plain_none_still_decides_the_branch(tmp_path: Path) -> None:
    """The twin: a local that is ``None`` in every run (no option can change it) still rules
    the traced branch out; no publisher is invented and the line is explained."""
    files = package("sim_runner", "'sim = sim_runner.main:main'", {
        "simulation": SIMULATION, "trace": TRACE,
        "main": MAIN.replace("{trace}", "None if trace is None else trace.expanduser()").replace(
            "args = _parser().parse_args(argv)", "args = _parser().parse_args(argv)\n        trace = None")})
    root = write(tmp_path, files)
    assert entities(root, TOPICS) == {"/sim_bridge": [("subscriptions", "/odom")]}
    assert reasons(root)[("sim_runner/sim_runner/simulation.py", 15)][0] == "missing"


# -- setattr over a table of parameter defaults ------------------------------------------------
FIELDS = "".join(f"        joint_{i}_limit: float = {i}.5\n" for i in range(14))
KEYS = "".join(f"                'joint_{i}_limit': config.joint_{i}_limit,\n" for i in range(14))
CONFIG = """
    from dataclasses import dataclass


    @dataclass
    class PolicyConfig:
        '''Everything the deployed policy reads, with the values used on the robot.'''

        control_frequency: float = 20.0
        use_left_arm: bool = False
        use_right_arm: bool = True
        left_arm_state_topic: str = '/left_arm/joint_states'
        right_arm_state_topic: str = '/right_arm/joint_states'
        right_arm_command_topic: str = '/teleop/right/servo_j'
{fields}
        @classmethod
        def from_node(cls, node):
            config = cls()
            defaults = {{
                'control_frequency': config.control_frequency,
                'use_left_arm': config.use_left_arm,
                'use_right_arm': config.use_right_arm,
                'left_arm_state_topic': config.left_arm_state_topic,
                'right_arm_state_topic': config.right_arm_state_topic,
                'right_arm_command_topic': config.right_arm_command_topic,
{keys}            }}
            for name, default in defaults.items():
                node.declare_parameter(name, default)
                setattr(config, name, node.get_parameter(name).value)
            return config
""".format(fields=FIELDS, keys=KEYS)
POLICY_NODE = """
    import rclpy
    from rclpy.node import Node
    from sensor_msgs.msg import JointState
    from std_msgs.msg import Float64MultiArray

    from policy_runner.config import PolicyConfig


    class PolicyNode(Node):
        def __init__(self):
            super().__init__('policy_runner')
            self.config = {load}
            if self.config.use_left_arm:
                self.create_subscription(JointState, self.config.left_arm_state_topic, self.on_left, 10)
            if self.config.use_right_arm:
                self.create_subscription(JointState, self.config.right_arm_state_topic, self.on_right, 10)
            self.command = self.create_publisher(
                Float64MultiArray, self.config.right_arm_command_topic, 10)

        def on_left(self, msg):
            pass

        def on_right(self, msg):
            self.command.publish(Float64MultiArray(data=list(msg.position)))


    def main():
        rclpy.init()
        rclpy.spin(PolicyNode())
"""


def _policy(tmp_path: Path, load: str, config: str = CONFIG) -> Path:
    return write(tmp_path, package("policy_runner", "'policy = policy_runner.policy_node:main'", {
        "config": config, "policy_node": POLICY_NODE.replace("{load}", load)}))


def test_setattr_over_a_long_table_of_defaults_keeps_each_key(tmp_path: Path) -> None:
    """Twenty keys, more than a value holds: each ``setattr`` still names its key and the
    parameter's default, so the left arm's branch (default off, a parameter may switch it on)
    is explored and every topic is named (ACT inference node: seven sites reported never
    reached)."""
    root = _policy(tmp_path, "PolicyConfig.from_node(self)")
    assert entities(root, TOPICS) == {"/policy_runner": [
        ("publishers", "/teleop/right/servo_j"), ("subscriptions", "/left_arm/joint_states"),
        ("subscriptions", "/right_arm/joint_states")]}


def test_setattr_of_names_read_from_a_file_keeps_no_default_for_sure(tmp_path: Path) -> None:
    """A configuration filled from a YAML file by names the analysis cannot know: any field
    may change, so the left arm's branch is explored too; each topic is its default or a
    name the file gives (only partly known)."""
    config = CONFIG.replace(
        "for name, default in defaults.items():\n"
        "                node.declare_parameter(name, default)\n"
        "                setattr(config, name, node.get_parameter(name).value)",
        "import yaml\n"
        "            with open(node.declare_parameter('config_file', '').value) as f:\n"
        "                for name, value in yaml.safe_load(f).items():\n"
        "                    setattr(config, name, value)")
    root = _policy(tmp_path, "PolicyConfig.from_node(self)", config)
    names = {name for _, name in entities(root, ("subscriptions",))["/policy_runner"]}
    assert names == {"/left_arm/joint_states", "/right_arm/joint_states", "?"}


def test_class_defaults_nothing_overwrites_still_decide_the_branch(tmp_path: Path) -> None:
    """The twin: the same configuration used as it is (no setattr, no parameter) keeps its
    defaults; the left arm's subscription is never created and none is invented."""
    root = _policy(tmp_path, "PolicyConfig()")
    assert entities(root, TOPICS) == {"/policy_runner": [
        ("publishers", "/teleop/right/servo_j"), ("subscriptions", "/right_arm/joint_states")]}


# -- explain: a type left unknown because names and types cannot be paired --------------------
SHUTDOWN = """
    import sys
    from dataclasses import dataclass

    import rclpy
    from lifecycle_msgs.srv import ChangeState
    from nav2_msgs.srv import ManageLifecycleNodes


    @dataclass(frozen=True)
    class Step:
        service: str
        kind: str
        command: int


    STEPS = (
        Step('/lifecycle_manager_navigation/manage_nodes', 'manager', 1),
        Step('/slam_toolbox/change_state', 'lifecycle', 4),
    )


    def call_step(node, step):
        if step.kind == 'manager':
            service_type = ManageLifecycleNodes
            request = ManageLifecycleNodes.Request(command=step.command)
        else:
            service_type = ChangeState
            request = ChangeState.Request()
            request.transition.id = step.command
        client = node.create_client(service_type, step.service)
        client.wait_for_service(timeout_sec=2.0)
        return client.call_async(request)


    def main():
        rclpy.init()
        node = rclpy.create_node('ordered_shutdown')
        for step in {steps}:
            call_step(node, step)
"""


def test_explain_names_the_types_it_cannot_pair_with_the_names(tmp_path: Path) -> None:
    """Two steps, each with its own service and type, through one call: the graph cannot
    pair them and leaves the type unknown; the reason names both types instead of calling a
    value bound to a known class unknown."""
    root = write(tmp_path, package("shutdown", "'shutdown = shutdown.ordered:main'",
                                   {"ordered": SHUTDOWN.replace("{steps}", "STEPS")}))
    status, why = reasons(root)[("shutdown/shutdown/ordered.py", 30)]
    assert status == "unknown"
    assert why == ("unknown type", "it is one of 2 types (lifecycle_msgs/srv/ChangeState, "
                   "nav2_msgs/srv/ManageLifecycleNodes) and which of its names goes with which "
                   "type is not known")


def test_one_name_with_two_possible_types_is_one_entity_per_type(tmp_path: Path) -> None:
    """The twin: one service whose kind the command line gives, so one name and two possible
    types; each type is an entity of its own and the site is complete, with no reason to give."""
    step = "(Step('/slam_toolbox/change_state', sys.argv[1], 4),)"
    root = write(tmp_path, package("shutdown", "'shutdown = shutdown.ordered:main'",
                                   {"ordered": SHUTDOWN.replace("{steps}", step)}))
    assert reasons(root)[("shutdown/shutdown/ordered.py", 30)] == ("complete", ())


# -- a guard that leaves the function names what passes it -------------------------------------
BRIDGE = """
    import rclpy
    from rclpy.node import Node
    from unitree_go.msg import LowState

    from go2_bridge.profile import load_profile

    LOWSTATE_TOPICS = ('/lowstate', '/lf/lowstate')


    class ControlBridge(Node):
        def __init__(self, profile):
            super().__init__('go2_control_bridge')
            control = profile.get('control', {})
            lowstate = str(control.get('lowstate_topic', '/lowstate'))
            if lowstate not in LOWSTATE_TOPICS:
                {refuse}
            self.create_subscription(LowState, lowstate, self.on_lowstate, 10)

        def on_lowstate(self, msg):
            self.get_logger().debug(f'battery {msg.bms_state.soc}')


    def main():
        rclpy.init()
        rclpy.spin(ControlBridge(load_profile()))
"""
PROFILE = """
    import json
    import os


    def load_profile():
        with open(os.environ['GO2_PROFILE']) as f:
            return json.load(f)
"""


def _bridge(tmp_path: Path, refuse: str) -> Path:
    return write(tmp_path, package("go2_bridge", "'bridge = go2_bridge.bridge:main'", {
        "bridge": BRIDGE.replace("{refuse}", refuse), "profile": PROFILE}))


def test_a_value_past_an_allowlist_guard_is_one_of_the_listed(tmp_path: Path) -> None:
    """``if lowstate not in LOWSTATE_TOPICS: raise``: past the guard the topic read from a
    JSON profile is one of the two allowed names (robot-scope's Go2 bridge)."""
    root = _bridge(tmp_path, "raise ValueError('lowstate_topic is not allowlisted')")
    assert entities(root, TOPICS) == {"/go2_control_bridge": [
        ("subscriptions", "/lf/lowstate"), ("subscriptions", "/lowstate")]}


def test_a_check_that_lets_every_value_through_names_nothing(tmp_path: Path) -> None:
    """The twin: the same check only logs, so any topic the profile names goes on; the name
    stays unknown and no allowed name is invented for it."""
    root = _bridge(tmp_path, "print('unusual lowstate topic', lowstate)")
    assert entities(root, TOPICS) == {"/go2_control_bridge": [("subscriptions", "?")]}


# -- rosidl_runtime_py: interface classes loaded by name ----------------------------------------
GATEWAY = """
    from rclpy.action import ActionClient
    from rosidl_runtime_py.utilities import get_action, get_message

    from nav_gateway.names import ODOM_TYPE, SCAN_TYPE


    class NavigationGateway:
        '''Serves the dashboard: robot state in, navigation goals out.'''

        def __init__(self, node):
            self.node = node
            odometry = get_message(ODOM_TYPE)
            self.node.create_subscription(odometry, '/odom', self.on_odom, 10)
            self.node.create_subscription(get_message(SCAN_TYPE), '/scan', self.on_scan, 10)
            self.goals = ActionClient(node, get_action('nav2_msgs/action/NavigateToPose'),
                                      'navigate_to_pose')

        def on_odom(self, msg):
            self.pose = msg.pose.pose

        def on_scan(self, msg):
            self.ranges = msg.ranges
"""
GATEWAY_NODE = """
    import rclpy
    from rclpy.node import Node

    from nav_gateway.gateway import NavigationGateway


    def main():
        rclpy.init()
        node = Node('dashboard_gateway')
        NavigationGateway(node)
        rclpy.spin(node)
"""


def _gateway(tmp_path: Path, names: str) -> Path:
    return write(tmp_path, package("nav_gateway", "'gateway = nav_gateway.main:main'", {
        "gateway": GATEWAY, "main": GATEWAY_NODE, "names": names}))


def test_get_message_of_a_full_name_is_that_message_class(tmp_path: Path) -> None:
    """``get_message('nav_msgs/msg/Odometry')`` is ``nav_msgs.msg.Odometry``: the
    subscriptions and the action client have their types (robot-scope's navigation
    gateway: eight sites with unknown types)."""
    root = _gateway(tmp_path, "ODOM_TYPE = 'nav_msgs/msg/Odometry'\nSCAN_TYPE = 'sensor_msgs/msg/LaserScan'\n")
    graph = build_graph(root)
    types = sorted((e.kind, e.name, e.type) for node in graph.nodes for e in node.entities
                   if e.kind in ("subscriptions", "action_clients"))
    assert types == [("action_clients", "/navigate_to_pose", "nav2_msgs/action/NavigateToPose"),
                     ("subscriptions", "/odom", "nav_msgs/msg/Odometry"),
                     ("subscriptions", "/scan", "sensor_msgs/msg/LaserScan")]


def test_get_message_of_a_short_or_unknown_name_stays_unknown(tmp_path: Path) -> None:
    """The twin: a short name (the library completes it by the kind asked for) and a name
    from the environment give no type; nothing is guessed."""
    root = _gateway(tmp_path, "import os\nODOM_TYPE = 'nav_msgs/Odometry'\nSCAN_TYPE = os.environ['SCAN_TYPE']\n")
    graph = build_graph(root)
    types = sorted((e.name, e.type) for node in graph.nodes for e in node.entities
                   if e.kind == "subscriptions")
    assert types == [("/odom", None), ("/scan", None)]


# -- .get(key, default) on a mapping read from a file ------------------------------------------
TELEOP = """
    import rclpy
    import yaml
    from geometry_msgs.msg import Twist
    from rclpy.node import Node
    from sensor_msgs.msg import Joy


    class JoyTeleop(Node):
        def __init__(self, config_path):
            super().__init__('joy_teleop')
            with open(config_path) as f:
                self.config = yaml.safe_load(f) or {}
            self.cmd = self.create_publisher(Twist, self.config.get('cmd_topic'{default}), 10)
            self.create_subscription(Joy, 'joy', self.on_joy, 10)

        def on_joy(self, msg):
            twist = Twist()
            twist.linear.x = msg.axes[1]
            self.cmd.publish(twist)


    def main():
        rclpy.init()
        rclpy.spin(JoyTeleop('/etc/teleop.yaml'))
"""


def _teleop(tmp_path: Path, default: str) -> Path:
    return write(tmp_path, package("joy_teleop", "'teleop = joy_teleop.teleop:main'", {
        "teleop": TELEOP.replace("{default}", default)}))


def test_get_with_a_default_on_an_unknown_mapping_keeps_the_default(tmp_path: Path) -> None:
    """``self.config.get('cmd_topic', '/cmd_vel')`` on a YAML file's contents: the default
    when the file lacks the key, something unknown otherwise; the known name stays in the
    graph, marked as only partly known (qyh task engine's gripper skills, rs2_listener)."""
    root = _teleop(tmp_path, ", '/cmd_vel'")
    assert entities(root, ("publishers",)) == {
        "/joy_teleop": [("publishers", "/cmd_vel"), ("publishers", "?")]}
    status, why = reasons(root)[("joy_teleop/joy_teleop/teleop.py", 13)]
    assert status == "unknown"
    assert why[0] == ("unknown name (known only partly: '/cmd_vel' on some paths, unknown "
                      "on others)")


def test_get_without_a_default_on_an_unknown_mapping_names_nothing(tmp_path: Path) -> None:
    """The twin: without a default nothing is known of the name, and none is invented."""
    root = _teleop(tmp_path, "")
    assert entities(root, ("publishers",)) == {"/joy_teleop": [("publishers", "?")]}
