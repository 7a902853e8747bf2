"""Findings a read of every finding on 18 further public repositories (a simulator bridge, a
scenario runner, robot bring-ups, drivers, LLM and HRI nodes) found false, each fixed by a
general mechanism: a realistic multi-file workspace with the pattern that was misjudged, and a
near-identical twin holding the real bug, which must still be reported."""
from __future__ import annotations

from pathlib import Path

from test_recall_mechanisms import findings
from test_workspace_discovery import PACKAGE_XML, setup_py, write


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
        "runner/package.xml": PACKAGE_XML.format(name="runner", build="ament_python"),
        "runner/setup.py": setup_py("runner", "'runner = runner.main:main'"),
        "runner/runner/__init__.py": "",
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
    assert [(code, path, line) for code, path, line, _ in reported] == [
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
        "rover/package.xml": PACKAGE_XML.format(name="rover", build="ament_python"),
        "rover/setup.py": setup_py("rover", "'odometry = rover.odometry:main', 'tracker = rover.tracker:main'"),
        "rover/rover/__init__.py": "",
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
        assert [(code, path, line) for code, path, line, _ in reported] == [
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
