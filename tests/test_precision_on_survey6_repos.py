"""Findings a read of every finding on 18 further public repositories (a simulator bridge, a
scenario runner, robot bring-ups, drivers, LLM and HRI nodes) found false, each fixed by a
general mechanism: a realistic multi-file workspace with the pattern that was misjudged, and a
near-identical twin holding the real bug, which must still be reported."""
from __future__ import annotations

from pathlib import Path

from flake8_rosgraph.findings import Finding
from flake8_rosgraph.graph.model import Location
from flake8_rosgraph.rules import merge_same_text

from test_recall_mechanisms import findings
from test_workspace_discovery import PACKAGE_XML, setup_py, write


def ament_python(name: str, scripts: str = "") -> dict[str, str]:
    """The files every ament_python package of these workspaces has: package.xml, setup.py
    with these ``console_scripts`` entries, and the module folder's ``__init__.py``."""
    return {f"{name}/package.xml": PACKAGE_XML.format(name=name, build="ament_python"),
            f"{name}/setup.py": setup_py(name, scripts),
            f"{name}/{name}/__init__.py": ""}


def sites(reported: list[tuple[str, str, int, str]]) -> list[tuple[str, str, int]]:
    """``(code, path, line)`` of each finding."""
    return [(code, path, line) for code, path, line, _ in reported]


# -- one call of one of two tree classes declares a parameter once ----------------------------------
TREES = """
    class PlainTree:
        def setup(self, node):
            node.declare_parameter('tick_period', 0.1)


    class LoggingTree(PlainTree):
        def setup(self, node):
            node.declare_parameter('tick_period', 0.1)
            node.declare_parameter('log_level', 'info')
"""

RUNNER = """
    import sys

    import rclpy
    from rclpy.node import Node

    from runner.trees import LoggingTree, PlainTree


    class Runner(Node):
        def __init__(self, verbose):
            super().__init__('runner')
            self.tree = LoggingTree() if verbose else PlainTree()
            {setup}


    def main():
        rclpy.init()
        rclpy.spin(Runner('-v' in sys.argv))
"""


def runner_workspace(root: Path, setup: str) -> Path:
    return write(root, {
        **ament_python("runner", "'runner = runner.main:main'"),
        "runner/runner/trees.py": TREES,
        "runner/runner/main.py": RUNNER.format(setup=setup),
    })


def test_one_call_of_one_of_two_classes_declares_once(tmp_path: Path) -> None:
    """scenario_execution: ``self.behaviour_tree.setup(...)`` reaches one of the tree classes'
    ``setup``; both declare ``default_snapshot_stream``, and the two callees of one call were
    counted as two calls in a row ("declared again", first declared at the same place)."""
    root = runner_workspace(tmp_path, "self.tree.setup(self)")
    assert findings(root, ["ROS102"]) == []


def test_the_tree_set_up_twice_still_declares_again(tmp_path: Path) -> None:
    """The twin: two calls in a row declare the names twice."""
    root = runner_workspace(tmp_path, "self.tree.setup(self)\n            self.tree.setup(self)")
    reported = findings(root, ["ROS102"])
    assert sites(reported) == [
        ("ROS102", "runner/runner/main.py", 14)]
    assert "is declared again on node '/runner'" in reported[0][3]


# -- a namespace pushed under a condition that does not hold is not pushed ----------------------
ODOMETRY = """
    import rclpy
    from nav_msgs.msg import Odometry
    from rclpy.node import Node
    from std_msgs.msg import Float64


    class WheelOdometry(Node):
        def __init__(self):
            super().__init__('wheel_odometry')
            self.odom_pub = self.create_publisher(Odometry, 'odom', 10)
            self.create_subscription(Float64, 'wheel_speed', self.on_speed, 10)

        def on_speed(self, msg):
            self.odom_pub.publish(Odometry())


    def main():
        rclpy.init()
        rclpy.spin(WheelOdometry())
"""

TRACKER = """
    import rclpy
    from nav_msgs.msg import Odometry
    from rclpy.node import Node
    from std_msgs.msg import Float64


    class Tracker(Node):
        def __init__(self):
            super().__init__('tracker')
            self.create_subscription(Odometry, '/odom', self.on_odom, 10)
            self.speed_pub = self.create_publisher(Float64, 'wheel_speed', 10)

        def on_odom(self, msg):
            self.speed_pub.publish(Float64(data=1.0))


    def main():
        rclpy.init()
        rclpy.spin(Tracker())
"""

ROVER_LAUNCH_PY = """
    from launch import LaunchDescription
    from launch.actions import DeclareLaunchArgument, GroupAction
    from launch.conditions import IfCondition
    from launch.substitutions import LaunchConfiguration
    from launch_ros.actions import Node, PushRosNamespace


    def generate_launch_description():
        use_namespace = LaunchConfiguration('use_namespace')
        namespace = LaunchConfiguration('namespace')
        return LaunchDescription([
            DeclareLaunchArgument('use_namespace', default_value='{use_namespace}'),
            DeclareLaunchArgument('namespace', default_value='rover'),
            GroupAction([
                PushRosNamespace(condition=IfCondition(use_namespace), namespace=namespace),
                Node(package='rover', executable='odometry', remappings=[('wheel_speed', '/wheel_speed')]),
            ]),
            Node(package='rover', executable='tracker'),
        ])
"""

ROVER_LAUNCH_XML = """
    <launch>
      <arg name="use_namespace" default="{use_namespace}"/>
      <group>
        <push_ros_namespace namespace="rover" if="$(var use_namespace)"/>
        <node pkg="rover" exec="odometry"><remap from="wheel_speed" to="/wheel_speed"/></node>
      </group>
      <node pkg="rover" exec="tracker"/>
    </launch>
"""


def rover_workspace(root: Path, use_namespace: str, launch: str = ROVER_LAUNCH_PY) -> Path:
    name = "rover.launch.py" if launch is ROVER_LAUNCH_PY else "rover.launch.xml"
    return write(root, {
        **ament_python("rover", "'odometry = rover.odometry:main', 'tracker = rover.tracker:main'"),
        "rover/rover/odometry.py": ODOMETRY,
        "rover/rover/tracker.py": TRACKER,
        f"rover/launch/{name}": launch.format(use_namespace=use_namespace),
    })


def test_a_namespace_pushed_under_a_false_condition_is_not_pushed(tmp_path: Path) -> None:
    """scenario_execution's gazebo_tf_publisher launch: ``PushRosNamespace(condition=
    IfCondition(use_namespace), …)`` with ``use_namespace`` false by default was pushed anyway,
    and the C++ node's ``tf`` became ``/leo_sim/tf`` ("did you mean '/tf'?")."""
    for launch in (ROVER_LAUNCH_PY, ROVER_LAUNCH_XML):
        root = rover_workspace(tmp_path / str(id(launch)), "False", launch)
        assert findings(root, ["ROS001", "ROS003"]) == []


def test_a_namespace_pushed_under_a_true_condition_is_still_a_slip(tmp_path: Path) -> None:
    """The twin: by default the odometry runs in ``/rover`` and the tracker reads ``/odom``."""
    for launch in (ROVER_LAUNCH_PY, ROVER_LAUNCH_XML):
        root = rover_workspace(tmp_path / str(id(launch)), "true", launch)
        reported = findings(root, ["ROS001", "ROS003"])
        assert sites(reported) == [
            ("ROS001", "rover/rover/odometry.py", 10), ("ROS003", "rover/rover/tracker.py", 10)]
        assert "did you mean '/odom'" in reported[0][3]


def test_a_namespace_pushed_under_an_unknown_condition_makes_the_names_unknown(tmp_path: Path) -> None:
    """A condition on a launch argument without a default may hold or not: the odometry's
    relative names are unknown, so neither end is judged."""
    root = rover_workspace(tmp_path, "False")
    launch = root / "rover/launch/rover.launch.py"
    launch.write_text(launch.read_text().replace(
        "DeclareLaunchArgument('use_namespace', default_value='False')",
        "DeclareLaunchArgument('use_namespace')"))
    assert findings(root, ["ROS001", "ROS003"]) == []


# -- a launch name given to an executable renames a node it only may create ----------------------
TREE_HELPER = """
    import rclpy
    from std_msgs.msg import String


    class BehaviourTree:
        def setup(self, node=None):
            {creation}
            self.status_pub = self.node.create_publisher(String, '~/status', 10)
"""

SCENARIO_RUNNER = """
    import rclpy
    from rclpy.node import Node

    from scenario.tree import BehaviourTree


    class ScenarioRunner:
        def __init__(self):
            self.node = rclpy.create_node('scenario_runner')
            self.tree = BehaviourTree()

        def run(self):
            self.tree.setup(node=self.node)
            rclpy.spin(self.node)


    def main():
        rclpy.init()
        ScenarioRunner().run()
"""

SCENARIO_LAUNCH = """
    from launch import LaunchDescription
    from launch_ros.actions import Node


    def generate_launch_description():
        return LaunchDescription([
            Node(package='scenario', executable='runner', name='scenario_execution'),
        ])
"""


def scenario_workspace(root: Path, creation: str) -> Path:
    return write(root, {
        **ament_python("scenario", "'runner = scenario.runner:main'"),
        "scenario/scenario/tree.py": TREE_HELPER.format(creation=creation),
        "scenario/scenario/runner.py": SCENARIO_RUNNER,
        "scenario/launch/scenario.launch.py": SCENARIO_LAUNCH,
    })


def test_a_launch_name_does_not_clash_with_a_node_created_only_on_some_path(tmp_path: Path) -> None:
    """scenario_execution: the tree's ``setup(node=None)`` creates a node of its own only when
    none is passed (``if node:``); the runner passes its node, which is true (rclpy's classes
    define no ``__bool__``), so the executable creates one node and the launch name renames it."""
    root = scenario_workspace(tmp_path, "if node:\n                self.node = node\n            else:\n"
                                        "                self.node = rclpy.create_node('tree')")
    assert findings(root, ["ROS007"]) == []


def test_a_launch_name_given_to_an_executable_of_two_nodes_is_still_reported(tmp_path: Path) -> None:
    """The twin: the tree always creates its own node, so both run as ``/scenario_execution``."""
    root = scenario_workspace(tmp_path, "self.node = rclpy.create_node('tree')")
    reported = findings(root, ["ROS007"])
    assert sites(reported) == [
        ("ROS007", "scenario/launch/scenario.launch.py", 7)]
    assert "gives its name to every node the executable creates" in reported[0][3]


# -- two test modules never run together ----------------------------------------------------------
LATENCY_TEST = """
    import unittest

    import rclpy
    from std_msgs.msg import String


    class TestLatency(unittest.TestCase):
        def setUp(self):
            rclpy.init()
            self.node = rclpy.create_node('test_node')
            self.publisher = self.node.create_publisher(String, '/probe', 10)
            self.node.create_timer(0.5, self.tick)

        def tick(self):
            self.publisher.publish(String(data='ping'))

        def tearDown(self):
            self.node.destroy_node()
            rclpy.shutdown()

        def test_latency(self):
            rclpy.spin_once(self.node, timeout_sec=1.0)
"""

SERVICE_TEST = """
    import unittest

    import rclpy
    from std_msgs.msg import {probe_type}


    class TestCounter(unittest.TestCase):
        def setUp(self):
            rclpy.init()
            self.received = []
            self.node = rclpy.create_node('test_node')
            self.node.create_subscription({probe_type}, '/probe', self.received.append, 10)

        def tearDown(self):
            self.node.destroy_node()
            rclpy.shutdown()

        def test_counts(self):
            rclpy.spin_once(self.node, timeout_sec=1.0)
            self.assertTrue(self.received)
"""


def checker_workspace(root: Path, probe_type: str, one_module: bool = False) -> Path:
    files = {
        **ament_python("checker"),
        "checker/test/test_latency.py": LATENCY_TEST,
        "checker/test/test_counter.py": SERVICE_TEST.format(probe_type=probe_type),
    }
    if one_module:
        # both test classes in one module: a probe and the node it feeds in one run
        counter = SERVICE_TEST.format(probe_type=probe_type).replace("'test_node'", "'counter_node'")
        files["checker/test/test_latency.py"] = LATENCY_TEST.replace(
            "from std_msgs.msg import String", f"from std_msgs.msg import String, {probe_type}") \
            + counter[counter.index("    class TestCounter"):]
        del files["checker/test/test_counter.py"]
    return write(root, files)


def test_two_test_modules_sharing_a_topic_name_are_not_one_system(tmp_path: Path) -> None:
    """scenario_execution: three test modules each create ``test_node`` and use ``/bla``, as
    ``String``, ``Int32`` and ``Bool``: each module's tests run on their own, so neither the
    types (ROS004) nor the node names (ROS007) clash."""
    root = checker_workspace(tmp_path, "Int32")
    assert findings(root, ["ROS004", "ROS007"]) == []


def test_a_type_mismatch_within_one_test_module_is_still_reported(tmp_path: Path) -> None:
    """The twin: the probe and the node it feeds are in one module and disagree on the type."""
    root = checker_workspace(tmp_path, "Int32", one_module=True)
    reported = findings(root, ["ROS004", "ROS007"])
    assert [(code, path) for code, path, _ in sites(reported)] == [("ROS004", "checker/test/test_latency.py")]
    assert "subscribed as 'std_msgs/msg/Int32' but published as 'std_msgs/msg/String'" in reported[0][3]


# -- code for both ROS versions writes the ROS 1 spelling of a field on its ROS 1 branch -------------
COMPAT = """
    import os

    ROS_VERSION = int(os.environ.get('ROS_VERSION', 0))
"""

CAMERA = """
    import math

    import rclpy
    from rclpy.node import Node
    from sensor_msgs.msg import CameraInfo

    from sim_bridge.compat import ROS_VERSION


    class CameraInfoPublisher(Node):
        def __init__(self):
            super().__init__('camera_info_publisher')
            self.pub = self.create_publisher(CameraInfo, 'camera_info', 10)
            self.create_timer(0.1, self.publish_info)

        def publish_info(self):
            info = CameraInfo()
            info.width, info.height = 800, 600
            fx = info.width / (2.0 * math.tan(math.radians(90.0) / 2.0))
            {projection}
            self.pub.publish(info)


    def main():
        rclpy.init()
        rclpy.spin(CameraInfoPublisher())
"""

BOTH_VERSIONS = """if ROS_VERSION == 1:
                info.K = [fx, 0.0, 400.0, 0.0, fx, 300.0, 0.0, 0.0, 1.0]
            else:
                info.k = [fx, 0.0, 400.0, 0.0, fx, 300.0, 0.0, 0.0, 1.0]"""


def bridge_workspace(root: Path, projection: str) -> Path:
    return write(root, {
        **ament_python("sim_bridge", "'camera = sim_bridge.camera:main'"),
        "sim_bridge/sim_bridge/compat.py": COMPAT,
        "sim_bridge/sim_bridge/camera.py": CAMERA.format(projection=projection),
    })


def test_the_ros1_branch_of_code_for_both_versions_is_not_judged(tmp_path: Path) -> None:
    """carla ros-bridge: ``if ROS_VERSION == 1: camera_info.K = …`` beside ``camera_info.k``
    on the ROS 2 branch; the ROS 1 names were reported as missing fields."""
    root = bridge_workspace(tmp_path, BOTH_VERSIONS)
    assert findings(root, ["ROS107"]) == []


def test_a_ros1_field_name_in_ros2_code_is_still_reported(tmp_path: Path) -> None:
    """The twin: code ported from ROS 1 keeps the capital ``K``, an AttributeError under ROS 2."""
    root = bridge_workspace(tmp_path, "info.K = [fx, 0.0, 400.0, 0.0, fx, 300.0, 0.0, 0.0, 1.0]")
    reported = findings(root, ["ROS107"])
    assert sites(reported) == [
        ("ROS107", "sim_bridge/sim_bridge/camera.py", 20)]
    assert reported[0][3] == ("sensor_msgs/msg/CameraInfo has no field 'K' "
                              "(its ROS 1 name: the ROS 2 field is 'k')")


# -- a script's main guard runs its statements in order ------------------------------------------
PATROL_SCRIPT = """
    import rclpy
    from geometry_msgs.msg import Twist
    from rclpy.node import Node


    class Patrol(Node):
        def __init__(self):
            super().__init__('patrol')
            self.cmd_pub = self.create_publisher(Twist, 'cmd_vel', 10)


    if __name__ == '__main__':
        {first}
        {second}
        rclpy.spin(patrol)
"""


def patrol_workspace(root: Path, first: str, second: str) -> Path:
    return write(root, {
        **ament_python("patrol"),
        "patrol/scripts/patrol_node.py": PATROL_SCRIPT.format(first=first, second=second),
    })


def test_a_node_created_before_init_in_a_main_guard_is_reported(tmp_path: Path) -> None:
    """Seeded in turtlebot3_behavior_demos' autonomy script: the statements of a main guard
    were all "conditional" (under an ``if``), so none ordered another and the swap was missed."""
    root = patrol_workspace(tmp_path, "patrol = Patrol()", "rclpy.init()")
    reported = findings(root, ["ROS105"])
    assert sites(reported) == [
        ("ROS105", "patrol/scripts/patrol_node.py", 13)]
    assert "node created before rclpy.init()" in reported[0][3]


def test_init_before_the_node_in_a_main_guard_is_quiet(tmp_path: Path) -> None:
    """The twin as written in the repository: init first."""
    root = patrol_workspace(tmp_path, "rclpy.init()", "patrol = Patrol()")
    assert findings(root, ["ROS105"]) == []


def test_a_node_created_on_one_branch_of_a_main_guard_is_not_ordered(tmp_path: Path) -> None:
    """A creation inside a choice (``Patrol() if fast else None``) may not run: not judged."""
    root = patrol_workspace(tmp_path, "patrol = Patrol() if len(__file__) > 3 else None", "rclpy.init()")
    assert findings(root, ["ROS105"]) == []


# -- a tf2 lookup returns a TransformStamped ---------------------------------------------------------
TF_TO_POSE = """
    import rclpy
    from geometry_msgs.msg import PoseStamped
    from rclpy.node import Node
    from rclpy.time import Time
    from tf2_ros import TransformException
    from tf2_ros.buffer import Buffer
    from tf2_ros.transform_listener import TransformListener


    class TfToPose(Node):
        def __init__(self):
            super().__init__('tf_to_pose')
            self.tf_buffer = Buffer()
            self.tf_listener = TransformListener(self.tf_buffer, self)
            self.pose_pub = self.create_publisher(PoseStamped, 'robot_pose', 10)
            self.create_timer(0.1, self.on_timer)

        def on_timer(self):
            try:
                t = self.tf_buffer.lookup_transform('map', 'base_link', Time())
            except TransformException:
                return
            pose = PoseStamped()
            pose.header = t.header
            pose.pose.position.x = t.transform.translation.x
            pose.pose.orientation = t.transform.rotation
            self.pose_pub.publish({published})


    def main():
        rclpy.init()
        rclpy.spin(TfToPose())
"""


def tf_pose_workspace(root: Path, published: str) -> Path:
    return write(root, {
        **ament_python("tf_tools", "'tf_to_pose = tf_tools.tf_to_pose:main'"),
        "tf_tools/tf_tools/tf_to_pose.py": TF_TO_POSE.format(published=published),
    })


def test_publishing_the_looked_up_transform_on_a_pose_publisher_is_reported(tmp_path: Path) -> None:
    """Seeded in scenario_execution's tf_to_pose_publisher: ``publish(t)`` instead of
    ``publish(pose)``; ``lookup_transform`` returned an unknown value, so nothing was judged."""
    root = tf_pose_workspace(tmp_path, "t")
    reported = findings(root, ["ROS104", "ROS107"])
    assert sites(reported) == [
        ("ROS104", "tf_tools/tf_tools/tf_to_pose.py", 27)]
    assert ("publishes a geometry_msgs/msg/TransformStamped message on a publisher of "
            "geometry_msgs/msg/PoseStamped") in reported[0][3]


def test_the_pose_built_from_the_transform_is_quiet(tmp_path: Path) -> None:
    """The twin as written: the fields read from the transform exist, the pose is published."""
    root = tf_pose_workspace(tmp_path, "pose")
    assert findings(root, ["ROS104", "ROS107"]) == []


# -- one end told with and without its hint is one finding --------------------------------------------
def test_a_finding_told_again_with_a_hint_is_one_finding() -> None:
    """aws-deepracer-offroad (seeded typo ``vehicle_stat``): the client as written and as the
    launch file starts it both lack a server; only the launched one's near name is known, and
    the line was printed twice, once without the hint."""
    here, server = Location("web/web/node.py", 123, 30), Location("ctrl/src/ctrl_node.cpp", 84, 5)
    bare = "service '/ctrl_pkg/vehicle_stat' has no server"
    hinted = bare + "; did you mean '/ctrl_pkg/vehicle_state' (served at ctrl/src/ctrl_node.cpp:84)?"
    merged = merge_same_text([Finding(here, "ROS008", bare), Finding(here, "ROS008", hinted, ((server, "server"),))])
    assert merged == [Finding(here, "ROS008", hinted, ((server, "server"),))]
    # another code, or another place, keeps its own line
    elsewhere = Location("web/web/node.py", 130, 30)
    assert len(merge_same_text([Finding(elsewhere, "ROS008", bare), Finding(here, "ROS008", hinted)])) == 2
    assert len(merge_same_text([Finding(here, "ROS001", bare), Finding(here, "ROS008", hinted)])) == 2


# -- a scoped remap under a condition that does not hold is not applied ------------------------------
SIM_LAUNCH = """
    from launch import LaunchDescription
    from launch.actions import DeclareLaunchArgument, GroupAction
    from launch.conditions import UnlessCondition
    from launch.substitutions import LaunchConfiguration
    from launch_ros.actions import Node, SetRemap


    def generate_launch_description():
        return LaunchDescription([
            DeclareLaunchArgument('real_robot', default_value='{real_robot}'),
            GroupAction([
                SetRemap(src='/odm', dst='/sim/odom',
                         condition=UnlessCondition(LaunchConfiguration('real_robot'))),
                Node(package='rover', executable='tracker'),
            ]),
        ])
"""


def test_a_remap_set_under_a_false_condition_is_not_applied(tmp_path: Path) -> None:
    """``SetRemap(…, condition=UnlessCondition(real_robot))`` with ``real_robot`` true by
    default remaps nothing, so its misspelt source is not judged in that configuration."""
    root = rover_workspace(tmp_path, "False")
    write(root, {"rover/launch/sim.launch.py": SIM_LAUNCH.format(real_robot="1")})
    assert findings(root, ["ROS202"]) == []


def test_a_remap_set_under_a_true_condition_is_still_judged(tmp_path: Path) -> None:
    """The twin: in simulation the remap applies, and ``/odm`` matches no name the tracker uses."""
    root = rover_workspace(tmp_path, "False")
    write(root, {"rover/launch/sim.launch.py": SIM_LAUNCH.format(real_robot="0")})
    reported = findings(root, ["ROS202"])
    assert sites(reported) == [("ROS202", "rover/launch/sim.launch.py", 12)]
    assert "did you mean '/odom'" in reported[0][3]


# -- two test modules never run together, but one spells the product's topic for the other ---------
MODEL_FEED_TEST = """
    import rclpy
    from std_msgs.msg import Float64MultiArray


    def test_model_is_consumed():
        rclpy.init()
        node = rclpy.create_node('test_model_feed')
        pub = node.create_publisher(Float64MultiArray, '/arm_model', 10)
        pub.publish(Float64MultiArray())
        node.destroy_node()
        rclpy.shutdown()
"""

MODEL_RATE_TEST = """
    import rclpy
    from std_msgs.msg import Float64MultiArray


    def test_model_rate():
        rclpy.init()
        node = rclpy.create_node('test_model_rate')
        received = []
        node.create_subscription(Float64MultiArray, {topic!r}, received.append, 10)
        rclpy.spin_once(node, timeout_sec=1.0)
        node.destroy_node()
        rclpy.shutdown()
"""


def two_test_modules(root: Path, topic: str) -> Path:
    return write(root, {
        **ament_python("arm_model"),
        "arm_model/test/test_feed.py": MODEL_FEED_TEST,
        "arm_model/test/test_rate.py": MODEL_RATE_TEST.format(topic=topic),
    })


def test_a_misspelt_topic_is_named_by_another_test_module_of_the_package(tmp_path: Path) -> None:
    """adl-ros2: a test subscribes ``/arm_modle``; another test module of the package publishes
    ``/arm_model``. They never run together, but the other module spells the name this one means."""
    reported = findings(two_test_modules(tmp_path, "/arm_modle"), ["ROS003"])
    assert [(code, path) for code, path, _ in sites(reported)] == [("ROS003", "arm_model/test/test_rate.py")]
    assert "did you mean '/arm_model' (published at arm_model/test/test_feed.py:8)" in reported[0][3]


def test_a_name_one_namespace_token_away_in_another_test_module_is_no_near_name(tmp_path: Path) -> None:
    """py_trees_ros: ``/monitor/arm_model`` in one test module and ``/arm_model`` in another are
    two tests' own topics, not a slip."""
    assert findings(two_test_modules(tmp_path, "/monitor/arm_model"), ["ROS001", "ROS003"]) == []
