"""Frameworks around rclpy: node base classes from libraries outside the workspace.

A company base class the analysis cannot see is either modelled by the user's own stub (a
ten-line TOML file passed with ``--stubs``) or, without one, its subclasses' rclpy calls of the
right shape still give a node of unknown name (``unresolved_base``). rqt plugins get the rqt
node as ``context.node``. Each case has its near-identical twin that must create nothing."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

from flake8_rosgraph.analysis import analyse, build_graph
from flake8_rosgraph.explain import explain
from flake8_rosgraph.graph.model import RosGraph
from flake8_rosgraph.rules import RuleConfig, run_rules

from test_workspace_discovery import PACKAGE_XML, write

#: Two packages written against acme_robot, a library installed from the company's wheel
#: (not in the tree): the driver publishes the joint states, the monitor subscribes to them
#: under a misspelt name, and sends the driver commands through a helper in its package.
ACME_WORKSPACE = {
    "arm_driver/package.xml": PACKAGE_XML.format(name="arm_driver", build="ament_python"),
    "arm_driver/arm_driver/__init__.py": "",
    "arm_driver/arm_driver/driver.py": """
        import rclpy
        from acme_robot import RobotNode
        from sensor_msgs.msg import JointState
        from std_msgs.msg import String

        from .topics import JOINTS


        class ArmDriver(RobotNode):
            def __init__(self):
                super().__init__('arm_driver')
                self.period = 0.02
                self.joints_pub = self.create_publisher(JointState, JOINTS, 10)
                self.create_subscription(String, 'arm_command', self.on_command, 10)
                self.timer = self.create_timer(self.period, self.publish_joints)

            def on_command(self, msg):
                self.get_logger().info(msg.data)

            def publish_joints(self):
                self.joints_pub.publish(JointState())


        def main():
            rclpy.init()
            rclpy.spin(ArmDriver())
    """,
    "arm_driver/arm_driver/topics.py": """
        JOINTS = 'joint_states'
    """,
    "arm_monitor/package.xml": PACKAGE_XML.format(name="arm_monitor", build="ament_python"),
    "arm_monitor/arm_monitor/__init__.py": "",
    "arm_monitor/arm_monitor/monitor.py": """
        import rclpy
        from acme_robot import RobotNode
        from sensor_msgs.msg import JointState

        from .commands import CommandSender


        class ArmMonitor(RobotNode):
            def __init__(self):
                super().__init__('arm_monitor')
                for name in ['joint_state']:
                    self.create_subscription(JointState, name, self.on_joints, 10)
                self.sender = CommandSender(self)

            def on_joints(self, msg):
                if len(msg.position) > 6:
                    self.sender.stop()


        def main():
            rclpy.init()
            rclpy.spin(ArmMonitor())
    """,
    "arm_monitor/arm_monitor/commands.py": """
        from std_msgs.msg import String


        class CommandSender:
            def __init__(self, node):
                self.pub = node.create_publisher(String, 'arm_command', 10)

            def stop(self):
                self.pub.publish(String(data='stop'))
    """,
}

#: The user's model of the base class: ten lines (docs/stubs.md, "Writing a stub for your own library").
ACME_STUB = """
[aliases]
"acme_robot.RobotNode" = "acme_robot.node.RobotNode"   # re-exported by acme_robot/__init__.py

[classes."acme_robot.node.RobotNode"]                   # acme_robot/node.py: class RobotNode(Node)
bases = ["rclpy.node.Node"]

[classes."acme_robot.node.RobotNode".methods.__init__]  # every robot node lives in /arm
params = "self, name, namespace='arm'"
effects = [{ kind = "node", target = "self", name = "name", namespace = "namespace" }]
"""


def _ends(graph: RosGraph) -> set[tuple]:
    return {(n.fqn, n.unresolved_base, e.kind, e.name, e.type) for n in graph.nodes for e in n.entities
            if e.kind != "parameters"}


def _codes(graph: RosGraph) -> list[tuple[str, str]]:
    return sorted((f.code, f.location.short()) for f in run_rules(graph, RuleConfig()))


def test_subclasses_of_an_unresolved_base_still_give_their_entities(tmp_path: Path) -> None:
    write(tmp_path, ACME_WORKSPACE)
    graph = build_graph(tmp_path)
    presumed = [(n.cls, n.name, n.namespace, n.unresolved_base, n.location.line) for n in graph.nodes]
    assert presumed == [("ArmDriver", None, None, "acme_robot.RobotNode", 9),
                        ("ArmMonitor", None, None, "acme_robot.RobotNode", 8)]
    # Relative names depend on the namespace the base class gives: unknown, never guessed.
    assert _ends(graph) == {
        (None, "acme_robot.RobotNode", "publishers", None, "sensor_msgs/msg/JointState"),
        (None, "acme_robot.RobotNode", "subscriptions", None, "std_msgs/msg/String"),
        (None, "acme_robot.RobotNode", "timers", None, None),
        (None, "acme_robot.RobotNode", "subscriptions", None, "sensor_msgs/msg/JointState"),
        (None, "acme_robot.RobotNode", "publishers", None, "std_msgs/msg/String"),  # via the helper
    }
    timer = next(e for n in graph.nodes for e in n.entities if e.kind == "timers")
    assert (timer.period, timer.callback) == (0.02, "ArmDriver.publish_joints")
    # Unknown names: the typo cannot be told from a match, and two nodes of unknown name are
    # no duplicate.
    assert _codes(graph) == []


def test_the_users_ten_line_stub_names_the_nodes_and_the_typo_is_found(tmp_path: Path) -> None:
    write(tmp_path / "ws", ACME_WORKSPACE)
    stub = tmp_path / "acme_robot.toml"
    stub.write_text(ACME_STUB, encoding="utf-8")
    assert len(ACME_STUB.strip().splitlines()) <= 10
    done = subprocess.run([sys.executable, "-m", "flake8_rosgraph", "graph", str(tmp_path / "ws"),
                           "--stubs", str(stub), "--format", "json"],
                          capture_output=True, text=True, check=True)
    data = json.loads(done.stdout)
    assert data["diagnostics"] == []
    assert [(n["fqn"], n["class"], "unresolved_base" in n) for n in data["nodes"]] == [
        ("/arm/arm_driver", "ArmDriver", False), ("/arm/arm_monitor", "ArmMonitor", False)]
    driver, monitor = data["nodes"]
    assert [(p["topic"], p["type"]) for p in driver["publishers"]] == [
        ("/arm/joint_states", "sensor_msgs/msg/JointState")]
    assert [s["topic"] for s in driver["subscriptions"]] == ["/arm/arm_command"]
    assert [(s["topic"], s["callback"]) for s in monitor["subscriptions"]] == [
        ("/arm/joint_state", "ArmMonitor.on_joints")]
    assert [p["topic"] for p in monitor["publishers"]] == ["/arm/arm_command"]

    graph = build_graph(tmp_path / "ws", [stub])
    assert _codes(graph) == [("ROS001", "arm_driver/arm_driver/driver.py:13"),
                             ("ROS003", "arm_monitor/arm_monitor/monitor.py:12")]


def test_explain_says_which_base_class_is_not_resolved(tmp_path: Path) -> None:
    write(tmp_path, ACME_WORKSPACE)
    graph, analysis = analyse(tmp_path)
    lines = [e.line() for e in explain(analysis, graph).explanations]
    assert ("arm_driver/arm_driver/driver.py:13:27: self.create_publisher: in the graph with unknown "
            "name; unknown node: class ArmDriver is presumed to be a node: its base class "
            "acme_robot.RobotNode is not resolved (imported from a library no stub models), so its "
            "name and namespace are unknown; a stub for the base class gives them") in lines


#: The same shapes of code where nothing is rclpy's: a recorder from another framework with
#: its own create_publisher(topic, msg) / create_timer(name, seconds), a workspace player class
#: with such a method (rqt_bag's Player), and instances of unmodelled library classes.
LOOKALIKES = {
    "bag_tools/package.xml": PACKAGE_XML.format(name="bag_tools", build="ament_python"),
    "bag_tools/bag_tools/__init__.py": "",
    "bag_tools/bag_tools/recorder.py": """
        import rclpy
        from rosbag_kit.recorder import Recorder, Channel
        from std_msgs.msg import String


        class TopicRecorder(Recorder):
            def __init__(self, topics):
                super().__init__('recorder')
                for topic in topics:
                    self.create_publisher(topic, String())          # (topic, message instance)
                self.create_timer('flush', 5.0)                     # (name, seconds)
                self.create_subscription(String, 'log')             # too few arguments
                self.create_client(String, 'x', 10, 20)             # too many
                self.create_service(String, 'reset', self.reset, queue=3)   # unknown keyword
                self.declare_parameter(7)                           # not a name
                Channel().create_publisher(String, 'chatter', 10)   # a library instance

            def reset(self, request, response):
                return response


        class Player:
            def __init__(self):
                self._publishers = {}

            def create_publisher(self, msg_type, topic, qos):
                self._publishers[topic] = (msg_type, qos)

            def start(self):
                self.create_publisher(String, 'clock', 10)


        def main():
            rclpy.init()
            TopicRecorder(['a', 'b']).record()
            Player().start()
    """,
}


def test_lookalike_calls_on_other_frameworks_create_nothing(tmp_path: Path) -> None:
    write(tmp_path, LOOKALIKES)
    graph, analysis = analyse(tmp_path)
    assert graph.nodes == []
    lines = [e.line() for e in explain(analysis, graph).explanations]
    assert ("bag_tools/bag_tools/recorder.py:11:9: self.create_timer: not in the graph: `self` is not "
            "known to be a modelled library object here; the base class rosbag_kit.recorder.Recorder "
            "is not resolved (imported from a library no stub models), and this call does not have "
            "the shape of rclpy.node.Node.create_timer (its arguments' number, names and kinds)") in lines
    # Player's own create_publisher is no creation site (explain.py, _own_method)
    assert not any(line.startswith("bag_tools/bag_tools/recorder.py:30:") for line in lines)


RQT_PACKAGE = {
    "rqt_arm/package.xml": """<?xml version="1.0"?>
        <package format="3"><name>rqt_arm</name><version>0.1.0</version><description>d</description>
        <maintainer email="a@b.c">a</maintainer><license>BSD</license>
        <exec_depend>rqt_gui_py</exec_depend>
        <export><build_type>ament_python</build_type><rqt_gui plugin="${prefix}/plugin.xml"/></export>
        </package>
    """,
    "rqt_arm/plugin.xml": """
        <library path="src">
          <class name="ArmPanel" type="rqt_arm.arm_panel.ArmPanel" base_class_type="rqt_gui_py::Plugin">
            <description>Arm panel</description>
          </class>
          <class name="Notes" type="rqt_arm.notes.Notes" base_class_type="rqt_gui_py::Plugin">
            <description>Notes without ROS</description>
          </class>
        </library>
    """,
    "rqt_arm/setup.py": """
        from setuptools import setup
        setup(name='rqt_arm', packages=['rqt_arm'], package_dir={'': 'src'})
    """,
    "rqt_arm/src/rqt_arm/__init__.py": "",
    "rqt_arm/src/rqt_arm/arm_panel.py": """
        from rqt_gui_py.plugin import Plugin
        from std_msgs.msg import String

        from .joint_view import JointView


        class ArmPanel(Plugin):
            def __init__(self, context):
                super(ArmPanel, self).__init__(context)
                self.setObjectName('ArmPanel')
                self._node = context.node
                self._view = JointView(context.node, 'arm')
                self._command = self._node.create_publisher(String, 'arm/command', 10)
                context.add_widget(self._view)

            def shutdown_plugin(self):
                self._node.destroy_publisher(self._command)
    """,
    "rqt_arm/src/rqt_arm/joint_view.py": """
        from python_qt_binding.QtWidgets import QWidget
        from sensor_msgs.msg import JointState
        from std_srvs.srv import Trigger


        class JointView(QWidget):
            def __init__(self, node, arm):
                super().__init__()
                self._sub = node.create_subscription(JointState, f'{arm}/joint_states', self.on_joints, 10)
                self._home = node.create_client(Trigger, arm + '/home')

            def on_joints(self, msg):
                self.update()
    """,
    # A Qt-only plugin on qt_gui's base class: rqt gives it no ROS node.
    "rqt_arm/src/rqt_arm/notes.py": """
        from qt_gui.plugin import Plugin


        class Notes(Plugin):
            def __init__(self, context):
                super().__init__(context)
                self._node = getattr(context, 'node', None)
                if self._node is not None:
                    self._node.create_timer(1.0, self.tick)

            def tick(self):
                pass
    """,
}


def test_rqt_plugins_create_their_entities_on_the_rqt_node(tmp_path: Path) -> None:
    write(tmp_path, RQT_PACKAGE)
    graph = build_graph(tmp_path)
    assert [(n.name, n.namespace, n.location.path, n.location.line) for n in graph.nodes] == [
        (None, "/", "rqt_arm/src/rqt_arm/arm_panel.py", 7)]
    assert {(e.kind, e.name, e.type, e.callback) for e in graph.nodes[0].entities} == {
        ("publishers", "/arm/command", "std_msgs/msg/String", None),
        ("subscriptions", "/arm/joint_states", "sensor_msgs/msg/JointState", "JointView.on_joints"),
        ("clients", "/arm/home", "std_srvs/srv/Trigger", None),
    }


def test_shipped_stand_ins_name_parameters_their_methods_have() -> None:
    from flake8_rosgraph.absint.library import load_library
    from flake8_rosgraph.analysis import builtin_stub_texts

    library = load_library(builtin_stub_texts())
    checked = 0
    for qualname, model in library.classes.items():
        for method, spec in model.stand_in_for_unresolved.items():
            found = library.method(qualname, method)
            assert found is not None and found.effects, (qualname, method)
            params = {p.name for p in found.signature.params}
            assert {param for param, _ in spec.kinds} <= params, (qualname, method)
            checked += 1
    assert checked == 6


#: A `ros2 fleet` command-line extension outside ros2cli, built on its node helpers.
CLI_PACKAGE = {
    "ros2fleet/package.xml": PACKAGE_XML.format(name="ros2fleet", build="ament_python"),
    "ros2fleet/setup.py": """
        from setuptools import setup

        setup(name='ros2fleet', packages=['ros2fleet'], entry_points={
            'ros2cli.command': ['fleet = ros2fleet.command.fleet:FleetCommand'],
            'ros2fleet.verb': ['battery = ros2fleet.verb.battery:BatteryVerb',
                               'ping = ros2fleet.verb.ping:PingVerb',
                               'list = ros2fleet.verb.list:ListVerb'],
        })
    """,
    "ros2fleet/ros2fleet/__init__.py": "",
    "ros2fleet/ros2fleet/command/__init__.py": "",
    "ros2fleet/ros2fleet/command/fleet.py": """
        from ros2cli.command import add_subparsers_on_demand, CommandExtension


        class FleetCommand(CommandExtension):
            def add_arguments(self, parser, cli_name):
                add_subparsers_on_demand(parser, cli_name, '_verb', 'ros2fleet.verb', required=False)

            def main(self, *, parser, args):
                return args._verb.main(args=args)
    """,
    "ros2fleet/ros2fleet/verb/__init__.py": "",
    "ros2fleet/ros2fleet/verb/battery.py": """
        from ros2cli.node.strategy import add_arguments, NodeStrategy
        from ros2cli.verb import VerbExtension
        from sensor_msgs.msg import BatteryState

        TOPIC = '/fleet/battery'


        class BatteryVerb(VerbExtension):
            def add_arguments(self, parser, cli_name):
                add_arguments(parser)

            def main(self, *, args):
                with NodeStrategy(args) as node:
                    node.create_subscription(BatteryState, TOPIC, self.show, 10)
                    node.spin_until_shutdown()

            def show(self, msg):
                print(msg.percentage)
    """,
    "ros2fleet/ros2fleet/verb/ping.py": """
        from ros2cli.node.direct import DirectNode
        from ros2cli.verb import VerbExtension
        from std_srvs.srv import Trigger


        class PingVerb(VerbExtension):
            def main(self, *, args):
                with DirectNode(args, node_name='fleet_ping') as node:
                    client = node.create_client(Trigger, 'fleet/ping')
                    return client.call(Trigger.Request())
    """,
    # Graph queries only: the daemon answers them, no entity is created.
    "ros2fleet/ros2fleet/verb/list.py": """
        from ros2cli.node.strategy import NodeStrategy
        from ros2cli.verb import VerbExtension


        class ListVerb(VerbExtension):
            def main(self, *, args):
                with NodeStrategy(args) as node:
                    for name, types in node.get_topic_names_and_types():
                        print(name, types)
    """,
}


def test_ros2cli_extensions_create_their_entities_on_the_cli_node(tmp_path: Path) -> None:
    write(tmp_path, CLI_PACKAGE)
    graph = build_graph(tmp_path)
    assert sorted(((n.name, n.namespace, n.location.path, n.location.line,
                    sorted((e.kind, e.name, e.type, e.callback) for e in n.entities))
                   for n in graph.nodes), key=repr) == [
        ("fleet_ping", "/", "ros2fleet/ros2fleet/verb/ping.py", 8,
         [("clients", "/fleet/ping", "std_srvs/srv/Trigger", None)]),
        (None, "/", "ros2fleet/ros2fleet/verb/battery.py", 13,
         [("subscriptions", "/fleet/battery", "sensor_msgs/msg/BatteryState", "BatteryVerb.show")]),
        # the strategy is modelled as the direct node it may fall back to (docs/stubs.md)
        (None, "/", "ros2fleet/ros2fleet/verb/list.py", 7, []),
    ]
    assert _codes(graph) == []


#: A launch action outside launch_ros that asks the launch's own ROS node for a client.
LAUNCH_ACTION_PACKAGE = {
    "arm_bringup/package.xml": PACKAGE_XML.format(name="arm_bringup", build="ament_python"),
    "arm_bringup/arm_bringup/__init__.py": "",
    "arm_bringup/arm_bringup/actions.py": """
        from launch.action import Action
        from launch_ros.ros_adapters import get_ros_node
        from std_srvs.srv import Trigger


        class WaitForArm(Action):
            def __init__(self, service, **kwargs):
                super().__init__(**kwargs)
                self.service = service

            def execute(self, context):
                node = get_ros_node(context)
                self.client = node.create_client(Trigger, self.service)
                return None
    """,
    "arm_bringup/launch/arm.launch.py": """
        from launch import LaunchDescription
        from arm_bringup.actions import WaitForArm


        def generate_launch_description():
            return LaunchDescription([WaitForArm('/arm/ready')])
    """,
}


def test_launch_actions_create_clients_on_the_launch_node(tmp_path: Path) -> None:
    write(tmp_path, LAUNCH_ACTION_PACKAGE)
    graph = build_graph(tmp_path)
    assert [(n.name, n.namespace, n.location.path, [(e.kind, e.name, e.type) for e in n.entities])
            for n in graph.nodes] == [
        (None, "/", "arm_bringup/arm_bringup/actions.py",
         [("clients", "/arm/ready", "std_srvs/srv/Trigger")])]


SIMPLE_NODE_PATROL = """
    import rclpy
    from {base_module} import Node
    from nav2_msgs.action import NavigateToPose
    from std_srvs.srv import Trigger


    class Patrol(Node):
        def __init__(self):
            super().__init__('patrol', namespace='robot1')
            self.client = self.create_client(Trigger, 'dock')
            self.create_timer(1.0, self.tick)

        def tick(self):
            self.client.wait_for_service()
            self.client.call(Trigger.Request())


    def main():
        rclpy.init()
        node = Patrol()
        {spin}
"""


def test_simple_node_subclasses_are_nodes_whose_synchronous_calls_are_safe(tmp_path: Path) -> None:
    """simple_node spins its node on a multi-threaded executor and gives each client a reentrant
    group, so a synchronous call in a callback is its purpose; the same code on rclpy's Node
    spun by rclpy.spin deadlocks."""
    write(tmp_path / "simple", {
        "patrol/package.xml": PACKAGE_XML.format(name="patrol", build="ament_python"),
        "patrol/patrol/__init__.py": "",
        "patrol/patrol/patrol.py": SIMPLE_NODE_PATROL.format(base_module="simple_node",
                                                             spin="node.join_spin()"),
        "patrol/patrol/navigate.py": """
            from simple_node import Node
            from nav2_msgs.action import NavigateToPose


            class Navigator(Node):
                def __init__(self):
                    super().__init__('navigator')
                    self.nav = self.create_action_client(NavigateToPose, 'navigate_to_pose')
                    self.create_action_server(NavigateToPose, 'patrol_to', self.execute)

                def execute(self, goal_handle):
                    self.nav.wait_for_server()
                    return NavigateToPose.Result()
        """,
    })
    graph = build_graph(tmp_path / "simple")
    assert sorted(((n.fqn, n.cls), sorted((e.kind, e.name) for e in n.entities if e.kind != "timers"))
                  for n in graph.nodes) == [
        (("/navigator", "Navigator"), [("action_clients", "/navigate_to_pose"),
                                       ("action_servers", "/patrol_to")]),
        (("/robot1/patrol", "Patrol"), [("clients", "/robot1/dock")]),
    ]
    assert [c for c, _ in _codes(graph)] == []
    write(tmp_path / "plain", {
        "patrol/package.xml": PACKAGE_XML.format(name="patrol", build="ament_python"),
        "patrol/patrol/patrol.py": SIMPLE_NODE_PATROL.format(base_module="rclpy.node",
                                                             spin="rclpy.spin(node)"),
    })
    assert [c for c, _ in _codes(build_graph(tmp_path / "plain"))] == ["ROS101"]
