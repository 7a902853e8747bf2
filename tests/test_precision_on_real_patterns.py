"""Findings a read of every finding on 87 public repositories found false, each fixed by a
general mechanism: a realistic multi-file workspace with the pattern that was misjudged, and a
near-identical twin holding the real bug, which must still be reported."""
from __future__ import annotations

from pathlib import Path

from test_recall_mechanisms import findings
from test_workspace_discovery import PACKAGE_XML, setup_py, write


# -- ROS002: a test harness that publishes a command and listens to it ------------------------------
GEAR_TEST = """
    import rclpy
    from rclpy.executors import SingleThreadedExecutor
    from std_msgs.msg import {sub_type}
    from std_msgs.msg import String


    class TestGearCommandBase:
        msgs_rx = []
        node = None

        @classmethod
        def setup_class(cls):
            rclpy.init()
            cls.msgs_rx = []
            cls.node = rclpy.create_node('test_gear_command')
            cls.sub = cls.node.create_subscription(
                {sub_type}, '/control/gear_cmd', lambda msg: cls.msgs_rx.append(msg), 10)
            cls.pub = cls.node.create_publisher(String, '/control/gear_cmd', 10)
            cls.executor = SingleThreadedExecutor()
            cls.executor.add_node(cls.node)

        @classmethod
        def teardown_class(cls):
            cls.node.destroy_node()
            rclpy.shutdown()

        def test_gear_command_goes_through(self):
            msg = String()
            msg.data = 'drive'
            while len(self.msgs_rx) < 3:
                self.pub.publish(msg)
                self.executor.spin_once(timeout_sec=0.1)
            assert self.msgs_rx[-1].data == 'drive'
"""

GEAR_NODE = """
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import String


    class GearReporter(Node):
        def __init__(self):
            super().__init__('gear_reporter')
            self.create_subscription(String, '/control/gear_cmd', self.on_gear, 10)
            self.report = self.create_publisher(String, '/vehicle/gear_report', 10)

        def on_gear(self, msg):
            self.report.publish(msg)


    def main():
        rclpy.init()
        rclpy.spin(GearReporter())
"""


def gear_workspace(root: Path, sub_type: str) -> Path:
    return write(root, {
        "sim_check/package.xml": PACKAGE_XML.format(name="sim_check", build="ament_python"),
        "sim_check/setup.py": setup_py("sim_check", "'gear_reporter = sim_check.gear_reporter:main'"),
        "sim_check/sim_check/__init__.py": "",
        "sim_check/sim_check/gear_reporter.py": GEAR_NODE,
        "sim_check/test/test_gear_command.py": GEAR_TEST.format(sub_type=sub_type),
    })


def test_a_test_harness_hearing_its_own_command_is_no_self_loop(tmp_path: Path) -> None:
    """autoware_tools' simulator_compatibility_test (5 false ROS002), rosbridge's and ros2cli's
    tests: the test publishes a command and subscribes to it with the same type, by design."""
    root = gear_workspace(tmp_path, "String")
    assert findings(root, ["ROS002"]) == []


def test_a_test_probe_of_another_type_on_its_own_topic_is_still_a_loop(tmp_path: Path) -> None:
    """The twin: the probe subscribes, with another type, the name the harness publishes."""
    root = gear_workspace(tmp_path, "Int32")
    assert [(code, path) for code, path, _, _ in findings(root, ["ROS002"])] == [
        ("ROS002", "sim_check/test/test_gear_command.py")]


def test_a_production_node_hearing_its_own_output_is_still_a_loop(tmp_path: Path) -> None:
    """Same type, but not a test: the subscription hears the node's own output."""
    root = gear_workspace(tmp_path, "String")
    reporter = root / "sim_check/sim_check/gear_reporter.py"
    reporter.write_text(reporter.read_text().replace("'/vehicle/gear_report'", "'/control/gear_cmd'"))
    assert [(code, path) for code, path, _, _ in findings(root, ["ROS002"])] == [
        ("ROS002", "sim_check/sim_check/gear_reporter.py")]


# -- ROS007: the nodes one executable runs, and what ties two nodes together --------------------------
BRIDGE_SCRIPT = """
    #!/usr/bin/env python3
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import String

    from web_bridge import ClientManager


    class BridgeServerNode(Node):
        def __init__(self):
            super().__init__('bridge_server')
            ClientManager.node_handle = self
            self.create_publisher(String, 'client_count', 10)


    def main():
        rclpy.init()
        rclpy.spin(BridgeServerNode())


    if __name__ == '__main__':
        main()
"""

CLIENT_MANAGER = """
    class ClientManager:
        node_handle = None
        clients = []

        @classmethod
        def add(cls, client):
            cls.clients.append(client)
"""

BRIDGE_CMAKE = """
    cmake_minimum_required(VERSION 3.5)
    project(web_bridge)
    find_package(ament_cmake_python REQUIRED)
    ament_python_install_package(web_bridge)
    install(PROGRAMS
      scripts/bridge_server.py
      scripts/bridge_server
      DESTINATION lib/${PROJECT_NAME}
    )
    ament_package()
"""

BRIDGE_LAUNCH = """
    <launch>
      <arg name="port" default="9090"/>
      <node pkg="web_bridge" exec="bridge_server" name="bridge_server" output="screen">
        <param name="port" value="$(var port)"/>
      </node>{second}
    </launch>
"""


def bridge_workspace(root: Path, second: str = "") -> Path:
    return write(root, {
        "web_bridge/package.xml": PACKAGE_XML.format(name="web_bridge", build="ament_cmake"),
        "web_bridge/CMakeLists.txt": BRIDGE_CMAKE,
        "web_bridge/web_bridge/__init__.py": CLIENT_MANAGER,
        "web_bridge/scripts/bridge_server": BRIDGE_SCRIPT,
        "web_bridge/scripts/bridge_server.py": BRIDGE_SCRIPT,
        "web_bridge/launch/bridge_launch.xml": BRIDGE_LAUNCH.format(second=second),
    })


def test_a_script_and_its_copy_with_an_extension_are_two_executables(tmp_path: Path) -> None:
    """rosbridge_suite installs ``scripts/rosbridge_websocket`` and ``rosbridge_websocket.py``:
    each defines its own node class of one name; launching one runs that one only."""
    root = bridge_workspace(tmp_path)
    assert findings(root, ["ROS007"]) == []


def test_launching_both_copies_under_one_name_is_still_a_duplicate(tmp_path: Path) -> None:
    second = """
      <node pkg="web_bridge" exec="bridge_server.py" name="bridge_server" output="screen"/>"""
    root = bridge_workspace(tmp_path, second)
    assert [(code, path, line) for code, path, line, _ in findings(root, ["ROS007"])] == [
        ("ROS007", "web_bridge/launch/bridge_launch.xml", 3),
        ("ROS007", "web_bridge/launch/bridge_launch.xml", 6)]


NAVIGATION = """
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import String
    from tf2_ros import Buffer, {tf_class}


    class Navigation(Node):
        def __init__(self):
            super().__init__('navigation')
            self.tf = {tf_class}({tf_args})
            self.create_{role}(String, '{topic}', {rest}10)

        def on_state(self, msg):
            self.get_logger().info(msg.data)


    def main():
        rclpy.init()
        rclpy.spin(Navigation())
"""

NAV_LAUNCH = """
    from launch import LaunchDescription
    from launch_ros.actions import Node


    def generate_launch_description():
        return LaunchDescription([
            Node(package='{package}', executable='{executable}', name='navigation'),
        ])
"""


def navigation_workspace(root: Path, topic: str) -> Path:
    """The rover's navigation and the training project's navigation: one class name, one node
    name, two packages, each started by a launch file of its own."""
    rover = NAVIGATION.format(tf_class="StaticTransformBroadcaster", tf_args="self", role="publisher",
                              topic="/nav_state", rest="")
    starter = NAVIGATION.format(tf_class="TransformListener", tf_args="Buffer(), self",
                                role="subscription", topic=topic, rest="self.on_state, ")
    return write(root, {
        "rover/package.xml": PACKAGE_XML.format(name="rover", build="ament_python"),
        "rover/setup.py": setup_py("rover", "'nav = rover.nav:main'"),
        "rover/rover/__init__.py": "",
        "rover/rover/nav.py": rover,
        "rover/launch/navigation.launch.py": NAV_LAUNCH.format(package="rover", executable="nav"),
        "starter/package.xml": PACKAGE_XML.format(name="starter", build="ament_python"),
        "starter/setup.py": setup_py("starter", "'navigation = starter.navigation:main'"),
        "starter/starter/__init__.py": "",
        "starter/starter/navigation.py": starter,
        "starter/launch/starter.launch.py": NAV_LAUNCH.format(package="starter", executable="navigation"),
    })


def test_two_same_named_classes_of_two_executables_are_not_one_executable(tmp_path: Path) -> None:
    """mrover-ros2: ``Navigation`` in ``navigation/nav.py`` and in the starter project; each
    executable creates its own class's node only, and using ``/tf_static`` (which every node
    may use) does not make the two run together."""
    root = navigation_workspace(tmp_path, "/starter_state")
    assert findings(root, ["ROS007"]) == []


def test_two_navigations_talking_over_a_topic_are_still_a_duplicate(tmp_path: Path) -> None:
    """The twin: the starter subscribes the rover's ``/nav_state``: they are one system."""
    root = navigation_workspace(tmp_path, "/nav_state")
    assert [(code, path) for code, path, _, _ in findings(root, ["ROS007"])] == [
        ("ROS007", "rover/launch/navigation.launch.py"), ("ROS007", "starter/launch/starter.launch.py")]


# -- ROS003: diagnostic_aggregator's output ----------------------------------------------------------
MONITOR = """
    import rclpy
    from diagnostic_msgs.msg import DiagnosticArray
    from rclpy.node import Node
    from std_msgs.msg import Bool


    class HardwareMonitor(Node):
        def __init__(self):
            super().__init__('hardware_monitor')
            self.create_subscription(DiagnosticArray, '{topic}', self.on_diagnostics, 10)
            self.create_subscription(Bool, '/motor_power', self.on_power, 10)
            self.pub = self.create_publisher(Bool, '/hardware_ok', 10)

        def on_diagnostics(self, msg):
            self.pub.publish(Bool(data=all(s.level == 0 for s in msg.status)))

        def on_power(self, msg):
            pass


    def main():
        rclpy.init()
        rclpy.spin(HardwareMonitor())
"""

POWER = """
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import Bool


    class Power(Node):
        def __init__(self):
            super().__init__('power')
            self.create_publisher(Bool, '/motor_power', 10)
            self.create_subscription(Bool, '/hardware_ok', self.on_ok, 10)

        def on_ok(self, msg):
            pass


    def main():
        rclpy.init()
        rclpy.spin(Power())
"""


def monitor_workspace(root: Path, topic: str) -> Path:
    return write(root, {
        "hcm/package.xml": PACKAGE_XML.format(name="hcm", build="ament_python"),
        "hcm/setup.py": setup_py("hcm", "'monitor = hcm.monitor:main', 'power = hcm.power:main'"),
        "hcm/hcm/__init__.py": "",
        "hcm/hcm/monitor.py": MONITOR.format(topic=topic),
        "hcm/hcm/power.py": POWER,
    })


def test_the_aggregated_diagnostics_are_infrastructure(tmp_path: Path) -> None:
    """bitbots_main: ``/diagnostics_agg`` is published by diagnostic_aggregator (C++)."""
    assert findings(monitor_workspace(tmp_path, "/diagnostics_agg"), ["ROS003"]) == []


def test_a_slip_of_the_aggregated_diagnostics_is_still_reported(tmp_path: Path) -> None:
    (finding,) = findings(monitor_workspace(tmp_path, "/diagnostic_agg"), ["ROS003"])
    assert finding[0] == "ROS003" and "did you mean '/diagnostics_agg'" in finding[3]


# -- ROS102: "declared again" on a node object that stands for several nodes --------------------------
CONNECTOR = """
    from rclpy.node import Node


    class Connector:
        '''Wraps a node of its own; every agent and service of the package makes one.'''

        def __init__(self, node_name, executor_type='single_threaded'):
            self.executor_type = executor_type
            self._node = Node(node_name)

        @property
        def node(self):
            return self._node
"""

AGENTS = """
    from perception.connector import Connector


    def make_agents():
        return [Connector(name) for name in ('asr', 'tts', 'nav', 'map', 'arm')]
"""

TOOLS = """
    from perception.connector import Connector


    def make_tools():
        return [Connector('tool_a'), Connector('tool_b'), Connector('tool_c'), Connector('tool_d'),
                Connector('tool_e', 'multi_threaded'), Connector('tool_f', 'multi_threaded'),
                Connector('tool_g', 'multi_threaded'), Connector('tool_h', 'multi_threaded')]
"""

SERVICES = """
    import os

    import rclpy

    from perception.agents import make_agents
    from perception.connector import Connector{tools_import}


    def main():
        rclpy.init()
        agents = {agents}
        detection = Connector('detection_service', executor_type='single_threaded')
        segmentation = Connector('segmentation_service', executor_type='single_threaded')
        legacy = os.getenv('LEGACY_NAMES', 'true') == 'true'
        detection.node.declare_parameter('enable_legacy_service_names', legacy)
        {second}.node.declare_parameter('enable_legacy_service_names', legacy)
        rclpy.spin(detection.node)
"""


def services_workspace(root: Path, second: str, tools: bool = True) -> Path:
    """With the tools, the package makes more connectors than the analysis keeps apart, so the
    two services' nodes share one object."""
    services = SERVICES.format(second=second, agents="make_agents() + make_tools()" if tools else "make_agents()",
                               tools_import="\n    from perception.tools import make_tools" if tools else "")
    return write(root, {
        "perception/package.xml": PACKAGE_XML.format(name="perception", build="ament_python"),
        "perception/setup.py": setup_py("perception", "'services = perception.services:main'"),
        "perception/perception/__init__.py": "",
        "perception/perception/connector.py": CONNECTOR,
        "perception/perception/agents.py": AGENTS,
        "perception/perception/services.py": services,
        **({"perception/perception/tools.py": TOOLS} if tools else {}),
    })


def test_one_declaration_on_each_of_two_merged_nodes_is_no_redeclaration(tmp_path: Path) -> None:
    """rai: two connectors' nodes, merged into one object by the bound on analysed contexts,
    each declare ``enable_legacy_service_names`` once."""
    assert findings(services_workspace(tmp_path, "segmentation"), ["ROS102"]) == []


def test_declaring_twice_on_one_node_is_still_a_redeclaration(tmp_path: Path) -> None:
    """The twin, with the nodes kept apart: declaring twice on one of them is reported."""
    (finding,) = findings(services_workspace(tmp_path, "detection", tools=False), ["ROS102"])
    assert finding[:3] == ("ROS102", "perception/perception/services.py", 16)
    assert "declared again" in finding[3]


# -- ROS102: a read guarded by ``except ParameterNotDeclaredException`` -------------------------------
STATE_LOGGER = """
    from rclpy.exceptions import ParameterAlreadyDeclaredException, ParameterException
    from rclpy.exceptions import ParameterNotDeclaredException


    class StateLogger:
        '''Logs state transitions; the behavior's node may or may not declare the settings.'''

        _node = None
        _log_folder = None
        _log_enabled = None

        @staticmethod
        def initialize_ros(node):
            StateLogger._node = node
            try:
                StateLogger._log_folder = node.get_parameter('log_folder').value
            except {caught}:
                node.get_logger().info("StateLogger: no 'log_folder' parameter, logging to ~/.logs")
                StateLogger._log_folder = '~/.logs'
            StateLogger._log_enabled = node.get_parameter('log_enabled').value
"""

BEHAVIOR = """
    import rclpy
    from rclpy.node import Node

    from behavior_core.state_logger import StateLogger


    class BehaviorOnboard(Node):
        def __init__(self):
            super().__init__('behavior_onboard')
            self.declare_parameter('log_enabled', False)
            StateLogger.initialize_ros(self)


    def main():
        rclpy.init()
        rclpy.spin(BehaviorOnboard())
"""


def behavior_workspace(root: Path, caught: str) -> Path:
    return write(root, {
        "behavior_core/package.xml": PACKAGE_XML.format(name="behavior_core", build="ament_python"),
        "behavior_core/setup.py": setup_py("behavior_core", "'onboard = behavior_core.onboard:main'"),
        "behavior_core/behavior_core/__init__.py": "",
        "behavior_core/behavior_core/state_logger.py": STATE_LOGGER.format(caught=caught),
        "behavior_core/behavior_core/onboard.py": BEHAVIOR,
    })


def test_a_read_that_handles_the_undeclared_parameter_is_no_bug(tmp_path: Path) -> None:
    """flexbe's RosState: ``try: node.get_parameter('breakpoints') except
    ParameterNotDeclaredException:`` logs and uses a default; a base class of the exception
    handles it as well."""
    for caught in ("ParameterNotDeclaredException", "ParameterException", "Exception"):
        assert findings(behavior_workspace(tmp_path / caught, caught), ["ROS102"]) == []


def test_a_read_in_a_try_that_catches_something_else_is_still_reported(tmp_path: Path) -> None:
    root = behavior_workspace(tmp_path, "ParameterAlreadyDeclaredException")
    (finding,) = findings(root, ["ROS102"])
    assert finding[:3] == ("ROS102", "behavior_core/behavior_core/state_logger.py", 16)
    assert "'log_folder' is never declared" in finding[3]


# -- ROS001: outputs for rviz ------------------------------------------------------------------------
PLANNER = """
    import rclpy
    from nav_msgs.msg import Path
    from rclpy.node import Node
    from std_msgs.msg import String
    from visualization_msgs.msg import Marker


    class Planner(Node):
        def __init__(self):
            super().__init__('planner')
            self.plan_pub = self.create_publisher(Path, 'plan', 10)
            self.vis_pub = self.create_publisher({vis_type}, '{vis_topic}', 1)
            self.create_subscription(String, 'goal_name', self.on_goal, 10)

        def on_goal(self, msg):
            self.plan_pub.publish(Path())
            self.vis_pub.publish({vis_type}())


    def main():
        rclpy.init()
        rclpy.spin(Planner())
"""

FOLLOWER = """
    import rclpy
    from nav_msgs.msg import Path
    from rclpy.node import Node
    from std_msgs.msg import String
    from visualization_msgs.msg import Marker


    class Follower(Node):
        def __init__(self):
            super().__init__('follower')
            self.create_subscription(Path, 'plan', self.on_plan, 10)
            self.goal_pub = self.create_publisher(String, 'goal_name', 10){vis_sub}

        def on_plan(self, msg):
            self.goal_pub.publish(String(data='dock'))

        def on_marker(self, msg):
            self.get_logger().info(f'marker {{msg.id}}')


    def main():
        rclpy.init()
        rclpy.spin(Follower())
"""


def planner_workspace(root: Path, vis_type: str, vis_topic: str, vis_sub: str = "") -> Path:
    return write(root, {
        "rover_nav/package.xml": PACKAGE_XML.format(name="rover_nav", build="ament_python"),
        "rover_nav/setup.py": setup_py("rover_nav", "'planner = rover_nav.planner:main', "
                                                  "'follower = rover_nav.follower:main'"),
        "rover_nav/rover_nav/__init__.py": "",
        "rover_nav/rover_nav/planner.py": PLANNER.format(vis_type=vis_type, vis_topic=vis_topic),
        "rover_nav/rover_nav/follower.py": FOLLOWER.format(vis_sub=vis_sub),
    })


def test_markers_for_rviz_are_an_interface(tmp_path: Path) -> None:
    """mrover's ``/nav_vis`` (``Marker``), bitbots' ``/basic_controls/update`` (an interactive
    marker server's): rviz draws them; nothing in the workspace subscribes."""
    assert findings(planner_workspace(tmp_path, "Marker", "nav_vis"), ["ROS001"]) == []


def test_another_unread_output_of_a_wired_node_is_still_reported(tmp_path: Path) -> None:
    """The twin: the same output as a plain ``String`` is the node's odd one out."""
    (finding,) = findings(planner_workspace(tmp_path, "String", "nav_vis"), ["ROS001"])
    assert finding[:2] == ("ROS001", "rover_nav/rover_nav/planner.py")


def test_a_misspelt_marker_topic_is_still_reported(tmp_path: Path) -> None:
    """The twin: a workspace node draws the markers; the planner's name is a slip of its."""
    vis_sub = "\n            self.create_subscription(Marker, 'nav_vis', self.on_marker, 1)"
    (finding,) = findings(planner_workspace(tmp_path, "Marker", "nav_viss", vis_sub), ["ROS001"])
    assert finding[:2] == ("ROS001", "rover_nav/rover_nav/planner.py") and "did you mean '/nav_vis'" in finding[3]


# -- ROS002: a subclass's output heard by a handler it builds ------------------------------------------
RL_NODE = """
    import rclpy
    from rclpy.node import Node


    class RLNode(Node):
        '''Base of the learned motion nodes: loads the policy, runs it on a timer.'''

        def __init__(self, node_name):
            super().__init__(node_name)
            self.declare_parameter('model', 'walk.onnx')
            self.create_timer(0.01, self.step)

        def step(self):
            pass


    def create_main(cls):
        def main():
            rclpy.init()
            rclpy.spin(cls())
        return main
"""

WALK_NODE = """
    from bitbots_msgs.msg import JointCommand

    from handlers.gravity_handler import GravityHandler
    from nodes.rl_node import RLNode, create_main


    class WalkNode(RLNode):
        def __init__(self):
            super().__init__(node_name='walk_node')
            self._joint_command_pub = self.create_publisher(JointCommand, 'walking_motor_goals', 10)
            self._gravity_handler = GravityHandler(self)


    main = create_main(WalkNode)
"""

GRAVITY_HANDLER = """
    from {module} import {msg_type}


    class GravityHandler:
        def __init__(self, node):
            self._node = node
            self._data = None
            self._sub = self._node.create_subscription({msg_type}, '{topic}', self._callback, 10)

        def _callback(self, msg):
            self._data = msg
"""


def walk_workspace(root: Path, module: str, msg_type: str, topic: str) -> Path:
    return write(root, {
        "rl_motion/package.xml": PACKAGE_XML.format(name="rl_motion", build="ament_python"),
        "rl_motion/setup.py": setup_py("rl_motion", "'walk = nodes.walk_node:main'"),
        "rl_motion/nodes/__init__.py": "",
        "rl_motion/nodes/rl_node.py": RL_NODE,
        "rl_motion/nodes/walk_node.py": WALK_NODE,
        "rl_motion/handlers/__init__.py": "",
        "rl_motion/handlers/gravity_handler.py": GRAVITY_HANDLER.format(module=module, msg_type=msg_type,
                                                                        topic=topic),
    })


def test_a_handler_hearing_the_subclass_output_is_a_loop(tmp_path: Path) -> None:
    """bitbots' walk_node: the base class creates the node, the subclass publishes, a handler it
    builds subscribes; the subclass's file is the node's own, so the ends are one program."""
    root = walk_workspace(tmp_path, "bitbots_msgs.msg", "JointCommand", "walking_motor_goals")
    assert [(code, path) for code, path, _, _ in findings(root, ["ROS002"])] == [
        ("ROS002", "rl_motion/handlers/gravity_handler.py")]


def test_a_handler_hearing_another_topic_is_no_loop(tmp_path: Path) -> None:
    root = walk_workspace(tmp_path, "sensor_msgs.msg", "Imu", "imu/data")
    assert findings(root, ["ROS002"]) == []


# -- ROS004: a test's end is judged against the product it tests ---------------------------------------
LED_STRIP = """
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import String


    class LedStrip(Node):
        def __init__(self):
            super().__init__('led_strip')
            self.create_subscription(String, '/led_strip/command', self.on_command, 10)
            self.display = self.create_publisher(String, '/led_strip/display', 10)

        def on_command(self, msg):
            self.display.publish(msg)


    def main():
        rclpy.init()
        rclpy.spin(LedStrip())
"""

BEHAVIOURS = """
    import std_msgs.msg as std_msgs


    class FlashLedStrip:
        '''A behaviour of the tree: the tree hands it its node in setup().'''

        def __init__(self, colour, topic_name='/led_strip/command'):
            self.colour = colour
            self.topic_name = topic_name
            self.node = None
            self.publisher = None

        def setup(self, **kwargs):
            self.node = kwargs['node']
            self.publisher = self.node.create_publisher(
                msg_type=std_msgs.{msg_type}, topic=self.topic_name, qos_profile=10)

        def update(self):
            self.publisher.publish(std_msgs.{msg_type}(data={value}))
"""

LED_TEST = """
    import rclpy

    from led_tutorials.behaviours import FlashLedStrip


    def test_flashing():
        rclpy.init()
        node = rclpy.create_node('tree')
        flash = FlashLedStrip(colour='red')
        flash.setup(node=node)
        flash.update()
        node.destroy_node()
        rclpy.shutdown()
"""


def led_workspace(root: Path, msg_type: str, value: str) -> Path:
    return write(root, {
        "led_tutorials/package.xml": PACKAGE_XML.format(name="led_tutorials", build="ament_python"),
        "led_tutorials/setup.py": setup_py("led_tutorials", "'led-strip = led_tutorials.led_strip:main'"),
        "led_tutorials/led_tutorials/__init__.py": "",
        "led_tutorials/led_tutorials/led_strip.py": LED_STRIP,
        "led_tutorials/led_tutorials/behaviours.py": BEHAVIOURS.format(msg_type=msg_type, value=value),
        "led_tutorials/tests/test_led_strip.py": LED_TEST,
    })


def test_a_behaviour_run_by_a_test_is_judged_against_the_product(tmp_path: Path) -> None:
    """py_trees_ros_tutorials: the tree's node exists only in a test, where the behaviour's
    publisher meets the mock LED strip's subscription; one end each, so the product decides."""
    (finding,) = findings(led_workspace(tmp_path, "Int32", "1"), ["ROS004"])
    assert finding[:2] == ("ROS004", "led_tutorials/led_tutorials/behaviours.py")


def test_a_behaviour_of_the_products_type_is_quiet(tmp_path: Path) -> None:
    assert findings(led_workspace(tmp_path, "String", "'red'"), ["ROS004"]) == []
