"""Findings a read of every finding on 13 further public repositories (rovers, arms, drivers,
ros2/demos and ros2/examples) found false, each fixed by a general mechanism: a realistic
multi-file workspace with the pattern that was misjudged, and a near-identical twin holding
the real bug, which must still be reported."""
from __future__ import annotations

from pathlib import Path

from flake8_rosgraph.findings import Finding, localised_message
from flake8_rosgraph.graph.model import Location
from flake8_rosgraph.rules import merge_same_text

from test_recall_mechanisms import findings
from test_workspace_discovery import PACKAGE_XML, setup_py, write


# -- one line printed twice: one finding -------------------------------------------------------------
RECONNECTING_DRIVER = """
    import time

    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import String


    class GnssDriver(Node):
        def __init__(self):
            super().__init__('gnss_driver')
            self.fix = self.create_publisher(String, 'fix_text', 10)
            self.create_timer(0.1, self.poll)
            self.create_timer(5.0, self.{second_callback})

        def poll(self):
            if not self.connected():
                self.reconnect()

        def send_correction(self):
            if not self.connected():
                self.reconnect()

        def connected(self):
            return False

        def reconnect(self):
            time.sleep({pause})


    def main():
        rclpy.init()
        rclpy.spin(GnssDriver())
"""


def gnss_workspace(root: Path, second_callback: str, pause: str = "2.0") -> Path:
    return write(root, {
        "gnss/package.xml": PACKAGE_XML.format(name="gnss", build="ament_python"),
        "gnss/setup.py": setup_py("gnss", "'driver = gnss.driver:main'"),
        "gnss/gnss/__init__.py": "",
        "gnss/gnss/driver.py": RECONNECTING_DRIVER.format(second_callback=second_callback, pause=pause),
    })


def test_one_callback_two_timers_run_is_reported_once(tmp_path: Path) -> None:
    """njord2026_ws's GNSS driver: two timers run one callback that reaches a sleep; the two
    timers gave two findings that read the same, at the callback's call."""
    root = gnss_workspace(tmp_path, "poll")
    reported = findings(root, ["ROS101"])
    assert [(code, line) for code, _, line, _ in reported] == [("ROS101", 17)]


def test_two_callbacks_reaching_the_sleep_are_two_findings(tmp_path: Path) -> None:
    """The twin: two callbacks reach the sleep, each reported at its own call."""
    root = gnss_workspace(tmp_path, "send_correction")
    reported = findings(root, ["ROS101"])
    assert [(code, line) for code, _, line, _ in reported] == [("ROS101", 17), ("ROS101", 21)]


def test_merging_keeps_every_related_location_once() -> None:
    here = Location("pkg/pkg/driver.py", 26, 13)
    timer_a, timer_b = Location("pkg/pkg/driver.py", 12, 9), Location("pkg/pkg/driver.py", 13, 9)
    merged = merge_same_text([Finding(here, "ROS101", "m", ((timer_b, "timer"),)),
                              Finding(here, "ROS101", "m", ((timer_a, "timer"), (timer_b, "timer")))])
    assert merged == [Finding(here, "ROS101", "m", ((timer_a, "timer"), (timer_b, "timer")))]


def test_a_partner_path_is_made_relative_once(tmp_path: Path) -> None:
    """ros2-lerobot-swerve-platform: two publishers at one line (one helper, two calls) made
    ``repos/x/repos/x/proxy.py:136`` of the partner's path; and ``proxy.py:13`` must not be
    rewritten inside ``proxy.py:136``."""
    pub_a, pub_b = Location("nodes/relay/proxy.py", 136, 19), Location("nodes/relay/proxy.py", 136, 25)
    early = Location("nodes/relay/proxy.py", 13, 5)
    finding = Finding(Location("nodes/relay/proxy.py", 141, 13), "ROS002",
                      "subscribes to topic '/b' that it publishes at nodes/relay/proxy.py:136 "
                      "and at nodes/relay/proxy.py:13",
                      ((pub_a, "publisher"), (pub_b, "publisher"), (early, "publisher")))
    root = tmp_path / "ws"
    text = localised_message(root, finding)
    assert text == (f"subscribes to topic '/b' that it publishes at {(root / 'nodes/relay/proxy.py').as_posix()}:136 "
                    f"and at {(root / 'nodes/relay/proxy.py').as_posix()}:13")


# -- ROS107: rospy modules of a package built for ROS 1 and ROS 2 ------------------------------------
DUAL_PACKAGE_XML = """<?xml version="1.0"?>
<package format="3"><name>multi_sync</name><version>0.1.0</version><description>d</description>
<maintainer email="a@b.c">a</maintainer><license>MIT</license>
<buildtool_depend condition="$ROS_VERSION == 1">catkin</buildtool_depend>
<buildtool_depend condition="$ROS_VERSION == 2">ament_cmake</buildtool_depend>
<depend condition="$ROS_VERSION == 1">rospy</depend>
<depend condition="$ROS_VERSION == 2">rclpy</depend>
<export><build_type condition="$ROS_VERSION == 1">catkin</build_type>
<build_type condition="$ROS_VERSION == 2">ament_cmake</build_type></export></package>
"""

SYNC_THREAD = """
    {ros_import}
    from diagnostic_msgs.msg import DiagnosticStatus, KeyValue
    from std_msgs.msg import String

    from multi_sync.naming import host_name


    class SyncThread:
        def __init__(self, uri):
            self.host = host_name(uri)

        def report(self):
            status = DiagnosticStatus()
            status.level = 0
            return [String('sync started on %s' % self.host), KeyValue('host', self.host), status]


    if __name__ == '__main__':
        print(SyncThread('localhost:11311').report())
"""

#: Shared by the package's ROS 1 and ROS 2 code: it joins the rospy module to an rclpy group.
NAMING = """
    try:
        import rclpy
    except ImportError:
        rclpy = None


    def host_name(uri):
        return uri.split(':')[0]
"""


def sync_workspace(root: Path, ros_import: str) -> Path:
    return write(root, {
        "multi_sync/package.xml": DUAL_PACKAGE_XML,
        "multi_sync/CMakeLists.txt": "cmake_minimum_required(VERSION 3.5)\nproject(multi_sync)\n",
        "multi_sync/src/multi_sync/__init__.py": "",
        "multi_sync/src/multi_sync/naming.py": NAMING,
        "multi_sync/src/multi_sync/sync_thread.py": SYNC_THREAD.format(ros_import=ros_import),
    })


def test_genpy_positional_messages_of_a_rospy_module_are_not_judged(tmp_path: Path) -> None:
    """fkie-multi-agent-suite: its discovery and sync packages build C++ for ROS 2 and keep
    their rospy modules, whose genpy messages take positional arguments (32 false ROS107)."""
    root = sync_workspace(tmp_path, "import rospy")
    assert findings(root, ["ROS107"]) == []


def test_positional_messages_of_an_rclpy_module_are_still_reported(tmp_path: Path) -> None:
    """The twin: the same module written for rclpy builds messages that raise (a ``byte`` takes
    ``bytes`` in ROS 2, and messages take keyword arguments only)."""
    root = sync_workspace(tmp_path, "import rclpy")
    assert [(code, line) for code, _, line, _ in findings(root, ["ROS107"])] == [("ROS107", 14), ("ROS107", 15), ("ROS107", 15)]


# -- ROS007: a script's node under ``if __name__ == '__main__':`` in a module another imports ----------
CAROUSEL = """
    #!/usr/bin/env python3
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import Float32

    from lab.hall_sensor import hall_state


    def publish_position(node, value):
        node.position.publish(Float32(data=float(hall_state(value))))


    if __name__ == '__main__':
        rclpy.init()
        node = Node('carousel')
        node.position = node.create_publisher(Float32, 'carousel/position', 10)
        rclpy.spin(node)
"""

HALL_SENSOR = """
    #!/usr/bin/env python3
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import Bool


    def hall_state(raw):
        return (raw & 0x0F) != 0


    {guard}
        rclpy.init()
        node = Node('hall_sensor')
        node.create_publisher(Bool, 'hall/state', 10)
        rclpy.spin(node)
"""

LAB_CMAKE = """
    cmake_minimum_required(VERSION 3.5)
    project(lab)
    find_package(ament_cmake_python REQUIRED)
    ament_python_install_package(lab)
    install(PROGRAMS lab/carousel.py lab/hall_sensor.py DESTINATION lib/${PROJECT_NAME})
    ament_package()
"""

LAB_LAUNCH = """
    from launch import LaunchDescription
    from launch_ros.actions import Node


    def generate_launch_description():
        return LaunchDescription([
            Node(package='lab', executable='carousel.py', name='carousel_inner'),
            Node(package='lab', executable='carousel.py', name='carousel_outer'),
        ])
"""


def lab_workspace(root: Path, guard: str) -> Path:
    return write(root, {
        "lab/package.xml": PACKAGE_XML.format(name="lab", build="ament_cmake"),
        "lab/CMakeLists.txt": LAB_CMAKE,
        "lab/lab/__init__.py": "",
        "lab/lab/carousel.py": CAROUSEL,
        "lab/lab/hall_sensor.py": HALL_SENSOR.format(guard=guard),
        "lab/launch/lab.launch.py": LAB_LAUNCH,
    })


def test_a_node_under_the_main_guard_of_an_imported_script_is_not_started(tmp_path: Path) -> None:
    """nova's science scripts: ``carousel.py`` imports a helper from ``hall_sensor.py``, whose
    ``if __name__ == '__main__':`` creates its own node; the launch action naming the carousel
    does not rename that node too (2 false ROS007)."""
    root = lab_workspace(tmp_path, "if __name__ == '__main__':")
    assert findings(root, ["ROS007"]) == []


def test_a_node_an_imported_module_creates_on_import_is_still_started(tmp_path: Path) -> None:
    """The twin: without the guard, importing the helper creates its node in the carousel's
    process, and the launch action's name goes to both."""
    root = lab_workspace(tmp_path, "if True:")
    assert [(code, line) for code, _, line, _ in findings(root, ["ROS007"])] == [("ROS007", 7), ("ROS007", 8)]


# -- ROS006/ROS002/ROS007: "empty = disabled", and one node configured by two bring-ups ---------------
SAFETY_MONITOR = """
    import rclpy
    from rclpy.node import Node
    from geometry_msgs.msg import Twist
    from std_msgs.msg import Float32MultiArray


    class SafetyMonitor(Node):
        def __init__(self):
            super().__init__('safety_monitor')
            self.declare_parameter('input_cmd_topic', 'cmd_vel_in')
            self.declare_parameter('output_cmd_topic', 'cmd_vel_out')
            self.declare_parameter('input_track_topic', '')   # empty = disabled
            self.declare_parameter('output_track_topic', '')  # empty = disabled
            self.input_cmd = str(self.get_parameter('input_cmd_topic').value)
            self.output_cmd = str(self.get_parameter('output_cmd_topic').value)
            self.input_track = str(self.get_parameter('input_track_topic').value)
            self.output_track = str(self.get_parameter('output_track_topic').value)
            self.create_subscription(Twist, self.input_cmd, self.on_cmd, 10)
            self.cmd_pub = self.create_publisher(Twist, self.output_cmd, 10)
            {track_guard}self.create_subscription(Float32MultiArray, self.input_track, self.on_track, 10)
            {indent}self.track_pub = self.create_publisher(Float32MultiArray, self.output_track, 10)

        def on_cmd(self, msg):
            self.cmd_pub.publish(msg)

        def on_track(self, msg):
            self.track_pub.publish(msg)


    def main():
        rclpy.init()
        rclpy.spin(SafetyMonitor())
"""

PLANNER = """
    import rclpy
    from rclpy.node import Node
    from geometry_msgs.msg import Twist


    class Planner(Node):
        def __init__(self):
            super().__init__('planner')
            self.create_publisher(Twist, 'cmd_vel_plan', 10)


    def main():
        rclpy.init()
        rclpy.spin(Planner())
"""

BRINGUP = """
    from launch import LaunchDescription
    from launch_ros.actions import Node


    def generate_launch_description():
        return LaunchDescription([
            Node(package='rover', executable='{executable}', name='safety_monitor',
                 parameters=[{{'input_cmd_topic': '{source}', 'output_cmd_topic': '{target}'}}]),
        ])
"""


#: The track relay's creation under ``if`` both names are set (written on one line with the call).
GUARDED = "if self.input_track and self.output_track:\n                "


def rover_workspace(root: Path, track_guard: str, second_executable: str = "safety_monitor") -> Path:
    return write(root, {
        "rover/package.xml": PACKAGE_XML.format(name="rover", build="ament_python"),
        "rover/setup.py": setup_py("rover", "'safety_monitor = rover.safety_monitor:main', "
                                            "'planner = rover.planner:main'"),
        "rover/rover/__init__.py": "",
        "rover/rover/safety_monitor.py": SAFETY_MONITOR.format(
            track_guard=track_guard, indent=" " * 4 if track_guard else ""),
        "rover/rover/planner.py": PLANNER,
        "rover/launch/mapping.launch.py": BRINGUP.format(
            executable="safety_monitor", source="cmd_vel_plan", target="/cmd_vel_safe"),
        "rover/launch/coverage.launch.py": BRINGUP.format(
            executable=second_executable, source="/cmd_vel_safe", target="cmd_vel_raw"),
    })


def test_an_optional_end_named_by_an_empty_default_is_not_judged(tmp_path: Path) -> None:
    """ros2-rover's lidar safety monitor creates its track relay only ``if`` both topic
    parameters are set; their empty defaults made 2 false ROS006, a self-loop over ``''``
    (ROS002) and two launched monitors "talking" over ``''`` (ROS007)."""
    root = rover_workspace(tmp_path, GUARDED)
    assert findings(root, ["ROS002", "ROS006"]) == []


def test_an_end_always_created_with_an_empty_default_is_still_invalid(tmp_path: Path) -> None:
    """The twin: created unconditionally, the empty default makes rclpy raise at start-up."""
    root = rover_workspace(tmp_path, "")
    assert [(code, line) for code, _, line, _ in findings(root, ["ROS006"])] == [("ROS006", 20), ("ROS006", 21)]


def test_one_node_configured_by_two_bringups_is_no_duplicate(tmp_path: Path) -> None:
    """ros2-rover: two bring-ups start the safety monitor under one name, one remapping its
    output onto what the other's input reads; the two instances are two deployments, not
    two nodes running together (3 false ROS007)."""
    root = rover_workspace(tmp_path, GUARDED)
    assert findings(root, ["ROS007"]) == []


def test_two_programs_of_one_name_in_two_bringups_that_talk_are_still_duplicates(tmp_path: Path) -> None:
    """The twin: the second bring-up starts another program under the same name, and the two
    talk: a system split over two launch files runs as one."""
    root = rover_workspace(tmp_path, GUARDED, "planner")
    reported = findings(root, ["ROS007"])
    assert [(code, path) for code, path, _, _ in reported] == [
        ("ROS007", "rover/launch/coverage.launch.py"), ("ROS007", "rover/launch/mapping.launch.py")]


# -- ROS001/ROS003: ros2_control controllers, and names handed to installed nodes as parameters --------
ARM_INTERFACE = """
    import rclpy
    from rclpy.node import Node
    from geometry_msgs.msg import TwistStamped, WrenchStamped
    from std_msgs.msg import Float64MultiArray, String


    class ArmInterface(Node):
        def __init__(self):
            super().__init__('arm_interface')
            controller = 'cartesian_vel_controller'
            self.velocity = self.create_publisher(TwistStamped, f'/{{controller}}/commands', 10)
            self.gripper = self.create_publisher(Float64MultiArray, '/gripper_controller/commands', 10)
            self.state = self.create_publisher(String, '/arm/state', 10)
            self.create_subscription(String, '/arm/goal', self.on_goal, 10)
            self.create_subscription(WrenchStamped, '{wrench}', self.on_wrench, 10)

        def on_goal(self, msg):
            self.state.publish(msg)

        def on_wrench(self, msg):
            self.get_logger().info(str(msg.wrench.force.x))


    def main():
        rclpy.init()
        rclpy.spin(ArmInterface())
"""

ARM_TELEOP = """
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import String


    class ArmTeleop(Node):
        def __init__(self):
            super().__init__('arm_teleop')
            self.goal = self.create_publisher(String, '/arm/goal', 10)
            self.create_subscription(String, '/arm/state', self.on_state, 10)

        def on_state(self, msg):
            self.get_logger().info(msg.data)


    def main():
        rclpy.init()
        rclpy.spin(ArmTeleop())
"""

CONTROLLERS_YAML = """
    controller_manager:
      ros__parameters:
        update_rate: 1000
        cartesian_vel_controller:
          type: arm_controllers/CartesianVelocityController
        gripper_controller:
          type: forward_command_controller/ForwardCommandController
        robot_state_broadcaster:
          type: arm_broadcasters/RobotStateBroadcaster
"""

ARM_LAUNCH = """
    from launch import LaunchDescription
    from launch.substitutions import PathJoinSubstitution
    from launch_ros.actions import Node
    from launch_ros.substitutions import FindPackageShare


    def generate_launch_description():
        controllers = PathJoinSubstitution([FindPackageShare('arm_bringup'), 'config', 'controllers.yaml'])
        return LaunchDescription([
            Node(package='controller_manager', executable='ros2_control_node',
                 parameters=[controllers], output='screen'),
            Node(package='controller_manager', executable='spawner',
                 arguments=['cartesian_vel_controller', 'robot_state_broadcaster']),
            Node(package='arm_interface', executable='arm_interface'),
            Node(package='arm_interface', executable='arm_teleop'),
        ])
"""


def arm_workspace(root: Path, wrench: str = "/robot_state_broadcaster/external_wrench") -> Path:
    return write(root, {
        "arm_interface/package.xml": PACKAGE_XML.format(name="arm_interface", build="ament_python"),
        "arm_interface/setup.py": setup_py("arm_interface", "'arm_interface = arm_interface.interface:main', "
                                                            "'arm_teleop = arm_interface.teleop:main'"),
        "arm_interface/arm_interface/__init__.py": "",
        "arm_interface/arm_interface/interface.py": ARM_INTERFACE.format(wrench=wrench),
        "arm_interface/arm_interface/teleop.py": ARM_TELEOP,
        "arm_bringup/package.xml": PACKAGE_XML.format(name="arm_bringup", build="ament_python"),
        "arm_bringup/setup.py": "from setuptools import setup\nsetup(name='arm_bringup')\n",
        "arm_bringup/config/controllers.yaml": CONTROLLERS_YAML,
        "arm_bringup/launch/arm.launch.py": ARM_LAUNCH,
    })


def test_the_topics_of_configured_controllers_are_their_ends(tmp_path: Path) -> None:
    """adl-ros2: the arm interface commands ``/cartesian_vel_controller/commands`` and reads
    ``/franka_robot_state_broadcaster/...``, controllers its controllers.yaml configures for the
    (installed) controller manager: C++ plugins are their other ends (3 false findings)."""
    root = arm_workspace(tmp_path)
    assert findings(root, ["ROS001", "ROS003"]) == []


def test_a_topic_of_no_configured_controller_is_still_dangling(tmp_path: Path) -> None:
    """The twin: the wrench is read under a broadcaster name no controller has (a slip of
    ``robot_state_broadcaster``); the interface's other subscription is wired, so it is
    the odd one out."""
    root = arm_workspace(tmp_path, "/robot_state_broadcster/external_wrench")
    assert [(code, line) for code, _, line, _ in findings(root, ["ROS001", "ROS003"])] == [("ROS003", 15)]


HEADING = """
    import rclpy
    from rclpy.node import Node
    from sensor_msgs.msg import Imu, MagneticField


    class Magnetometer(Node):
        def __init__(self):
            super().__init__('magnetometer')
            self.field = self.create_publisher(MagneticField, '/mag/field', 10)
            self.heading = self.create_publisher(Imu, '{heading}', 10)
            self.create_timer(0.1, self.read)

        def read(self):
            self.field.publish(MagneticField())
            self.heading.publish(Imu())


    def main():
        rclpy.init()
        rclpy.spin(Magnetometer())
"""

COMPASS = """
    import rclpy
    from rclpy.node import Node
    from sensor_msgs.msg import MagneticField


    class CompassDisplay(Node):
        def __init__(self):
            super().__init__('compass_display')
            self.create_subscription(MagneticField, '/mag/field', self.show, 10)

        def show(self, msg):
            self.get_logger().info(str(msg.magnetic_field.x))


    def main():
        rclpy.init()
        rclpy.spin(CompassDisplay())
"""

EKF_YAML = """
    ekf_filter_node:
      ros__parameters:
        frequency: 30.0
        world_frame: odom
        odom0: /wheel/odometry
        imu0: /mag/heading_imu
        imu0_config: [false, false, false, false, false, true]
"""

LOCALIZATION_LAUNCH = """
    import os

    from ament_index_python.packages import get_package_share_directory
    from launch import LaunchDescription
    from launch_ros.actions import Node


    def generate_launch_description():
        params = os.path.join(get_package_share_directory('rover_localization'), 'config', 'ekf.yaml')
        return LaunchDescription([
            Node(package='robot_localization', executable='ekf_node', name='ekf_filter_node',
                 parameters=[params]),
            Node(package='rover_sensors', executable='magnetometer'),
            Node(package='rover_sensors', executable='compass_display'),
        ])
"""


def localization_workspace(root: Path, heading: str) -> Path:
    return write(root, {
        "rover_sensors/package.xml": PACKAGE_XML.format(name="rover_sensors", build="ament_python"),
        "rover_sensors/setup.py": setup_py("rover_sensors", "'magnetometer = rover_sensors.magnetometer:main', "
                                                            "'compass_display = rover_sensors.compass:main'"),
        "rover_sensors/rover_sensors/__init__.py": "",
        "rover_sensors/rover_sensors/magnetometer.py": HEADING.format(heading=heading),
        "rover_sensors/rover_sensors/compass.py": COMPASS,
        "rover_localization/package.xml": PACKAGE_XML.format(name="rover_localization", build="ament_python"),
        "rover_localization/setup.py": "from setuptools import setup\nsetup(name='rover_localization')\n",
        "rover_localization/config/ekf.yaml": EKF_YAML,
        "rover_localization/launch/localization.launch.py": LOCALIZATION_LAUNCH,
    })


def test_a_name_an_installed_node_is_configured_with_is_its_end(tmp_path: Path) -> None:
    """nova: robot_localization's EKF reads ``imu1: /mag/heading_imu`` from the parameter file
    the launch file hands it; the magnetometer's heading output is its input."""
    root = localization_workspace(tmp_path, "/mag/heading_imu")
    assert findings(root, ["ROS001"]) == []


def test_a_name_no_installed_node_is_configured_with_is_still_dangling(tmp_path: Path) -> None:
    """The twin: the heading goes to a name the EKF is not configured with."""
    root = localization_workspace(tmp_path, "/mag/heading")
    assert [(code, line) for code, _, line, _ in findings(root, ["ROS001"])] == [("ROS001", 10)]


# -- ROS003: a launched node given a parameter file the workspace does not hold -----------------------
DELAY_NODE = """
    import importlib

    import rclpy
    from rclpy.node import Node


    class DelayNode(Node):
        def __init__(self):
            super().__init__('delay_node')
            self.declare_parameter('message_type', 'std_msgs/msg/String')
            self.declare_parameter('input_topic', 'input_topic')
            self.declare_parameter('output_topic', 'output_topic')
            package, _, name = self.get_parameter('message_type').value.split('/')
            message = getattr(importlib.import_module(package + '.msg'), name)
            self.out = self.create_publisher(message, self.get_parameter('output_topic').value, 10)
            self.create_subscription(message, self.get_parameter('input_topic').value, self.out.publish, 10)


    def main():
        rclpy.init()
        rclpy.spin(DelayNode())
"""

RIM_NODE = """
    import rclpy
    from rclpy.node import Node
    from geometry_msgs.msg import PoseStamped
    from std_msgs.msg import String


    class RimNode(Node):
        def __init__(self):
            super().__init__('rim_node')
            self.declare_parameter('rim_topic', '/rim_delayed')
            self.create_subscription(String, self.get_parameter('rim_topic').value, self.on_rim, 10)
            self.create_subscription(String, '/rim', self.on_rim, 10)
            self.pose = self.create_publisher(PoseStamped, '/haptic/pose', 10)

        def on_rim(self, msg):
            self.pose.publish(PoseStamped())


    def main():
        rclpy.init()
        rclpy.spin(RimNode())
"""

RIM_MODEL = """
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import String


    def main():
        rclpy.init()
        node = Node('rim_model')
        rim = node.create_publisher(String, '/rim', 10)
        node.create_timer(0.01, lambda: rim.publish(String(data='rim')))
        rclpy.spin(node)
"""

RIM_LAUNCH = """
    from launch import LaunchDescription
    from launch.actions import DeclareLaunchArgument
    from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
    from launch_ros.actions import Node
    from launch_ros.substitutions import FindPackageShare


    def generate_launch_description():
        config = PathJoinSubstitution([FindPackageShare('rim'), 'config', LaunchConfiguration('config_file')])
        return LaunchDescription([
            DeclareLaunchArgument('config_file', default_value='{config_file}'),
            Node(package='rim', executable='delay_node', name='rim_delay', parameters=[config]),
            Node(package='rim', executable='rim_node', name='rim_node', parameters=[config]),
            Node(package='rim', executable='rim_model'),
        ])
"""

RIM_YAML = """
    rim_delay:
      ros__parameters:
        input_topic: /rim
        output_topic: /rim_delayed
    rim_node:
      ros__parameters:
        rim_topic: /rim_delayed
"""


def rim_workspace(root: Path, config_file: str) -> Path:
    return write(root, {
        "rim/package.xml": PACKAGE_XML.format(name="rim", build="ament_python"),
        "rim/setup.py": setup_py("rim", "'delay_node = rim.delay_node:main', 'rim_node = rim.rim_node:main', "
                                        "'rim_model = rim.rim_model:main'"),
        "rim/rim/rim_model.py": RIM_MODEL,
        "rim/rim/__init__.py": "",
        "rim/rim/delay_node.py": DELAY_NODE,
        "rim/rim/rim_node.py": RIM_NODE,
        "rim/config/rim_sim.yaml": RIM_YAML,
        "rim/launch/rim.launch.py": RIM_LAUNCH.format(config_file=config_file),
    })


def test_names_a_missing_parameter_file_may_set_are_unknown(tmp_path: Path) -> None:
    """adl-ros2: the launch file's default parameter file is not in the workspace (the user
    passes ``config_file:=rim_fr3_config.yaml``); the delay node's output, named by a
    parameter that file sets, is not its code default, and the RIM node's input may be it."""
    root = rim_workspace(tmp_path, "rim_default.yaml")
    assert findings(root, ["ROS003"]) == []


def test_names_a_readable_parameter_file_leaves_alone_keep_their_defaults(tmp_path: Path) -> None:
    """The twin: the launch file's file is in the workspace and names the delay output
    ``/rim_delayed``, which the RIM node reads; a misspelt setting of the RIM node's input is
    reported (at its subscription, named by the setting)."""
    root = rim_workspace(tmp_path, "rim_sim.yaml")
    assert findings(root, ["ROS003"]) == []
    config = root / "rim/config/rim_sim.yaml"
    config.write_text(config.read_text().replace("rim_topic: /rim_delayed", "rim_topic: /rim_delyed"))
    assert [(code, path) for code, path, _, _ in findings(root, ["ROS003"])] == [("ROS003", "rim/rim/rim_node.py")]


# -- ROS001 (power): a namespace slip between two launch files of one robot ---------------------------
LOW_CMD = """
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import Float32MultiArray


    class MasterCmd(Node):
        def __init__(self):
            super().__init__('master_cmd')
            self.create_subscription(Float32MultiArray, 'robot_low_cmd', self.on_cmd, 10)
            self.servo = self.create_publisher(Float32MultiArray, 'low/servo_cmd', 10)

        def on_cmd(self, msg):
            self.servo.publish(msg)


    def main():
        rclpy.init()
        rclpy.spin(MasterCmd())
"""

TELEOP = """
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import Float32MultiArray


    class VrTeleop(Node):
        def __init__(self):
            super().__init__('vr_teleop')
            self.cmd = self.create_publisher(Float32MultiArray, '{topic}', 10)
            self.create_timer(0.02, self.send)

        def send(self):
            self.cmd.publish(Float32MultiArray())


    def main():
        rclpy.init()
        rclpy.spin(VrTeleop())
"""

ROBOT_LAUNCH = """
    from launch import LaunchDescription
    from launch_ros.actions import Node


    def generate_launch_description():
        return LaunchDescription([
            Node(package='{package}', executable='{executable}', namespace='{namespace}'),
        ])
"""


def robot_workspace(root: Path, topic: str, teleop_namespace: str = "alfie") -> Path:
    return write(root, {
        "alfie_bringup/package.xml": PACKAGE_XML.format(name="alfie_bringup", build="ament_python"),
        "alfie_bringup/setup.py": setup_py("alfie_bringup", "'master_cmd = alfie_bringup.master_cmd:main'"),
        "alfie_bringup/alfie_bringup/__init__.py": "",
        "alfie_bringup/alfie_bringup/master_cmd.py": LOW_CMD,
        "alfie_bringup/launch/bringup.launch.py": ROBOT_LAUNCH.format(
            package="alfie_bringup", executable="master_cmd", namespace="alfie"),
        "alfie_vr/package.xml": PACKAGE_XML.format(name="alfie_vr", build="ament_python"),
        "alfie_vr/setup.py": setup_py("alfie_vr", "'vr_teleop = alfie_vr.vr_teleop:main'"),
        "alfie_vr/alfie_vr/__init__.py": "",
        "alfie_vr/alfie_vr/vr_teleop.py": TELEOP.format(topic=topic),
        "alfie_vr/launch/teleop.launch.py": ROBOT_LAUNCH.format(
            package="alfie_vr", executable="vr_teleop", namespace=teleop_namespace),
    })


def test_a_teleop_writing_the_robot_namespace_out_is_a_slip(tmp_path: Path) -> None:
    """alfiebot (seeded): the teleop, launched in ``/alfie`` by its own launch file, publishes
    ``/robot_low_cmd``; the bring-up's ``robot_low_cmd`` lands in ``/alfie``. The two launch
    files start one robot, so the near name counts across them."""
    root = robot_workspace(tmp_path, "/robot_low_cmd")
    assert [(code, path) for code, path, _, _ in findings(root, ["ROS001", "ROS003"])] == [
        ("ROS001", "alfie_vr/alfie_vr/vr_teleop.py"), ("ROS003", "alfie_bringup/alfie_bringup/master_cmd.py")]


def test_a_teleop_writing_the_robot_namespace_in_is_wired(tmp_path: Path) -> None:
    root = robot_workspace(tmp_path, "/alfie/robot_low_cmd")
    assert findings(root, ["ROS001", "ROS003"]) == []


def test_launch_files_of_two_namespaces_stay_interfaces(tmp_path: Path) -> None:
    """Launched in another namespace, the teleop is another deployment: a namespace set by
    launch is a choice, not a slip."""
    root = robot_workspace(tmp_path, "/robot_low_cmd", teleop_namespace="operator")
    assert findings(root, ["ROS001", "ROS003"]) == []


# -- ROS001/ROS003: a package whose launch file builds its nodes in a way the analysis cannot follow ---
GPS_PREPROCESSOR = """
    import rclpy
    from rclpy.node import Node
    from sensor_msgs.msg import NavSatFix


    class GpsPreprocessor(Node):
        def __init__(self):
            super().__init__('gps_preprocessor')
            self.out = self.create_publisher(NavSatFix, 'fix/filtered', 10)
            self.create_subscription(NavSatFix, '{fix}', self.on_fix, 10)

        def on_fix(self, msg):
            self.out.publish(msg)


    def main():
        rclpy.init()
        rclpy.spin(GpsPreprocessor())
"""

GPS_SPOOFER = """
    import rclpy
    from rclpy.node import Node
    from sensor_msgs.msg import NavSatFix


    class GpsSpoofer(Node):
        def __init__(self):
            super().__init__('gps_spoofer')
            self.out = self.create_publisher(NavSatFix, 'fix/out', 10)
            self.create_subscription(NavSatFix, 'fix/in', self.out.publish, 10)


    def main():
        rclpy.init()
        rclpy.spin(GpsSpoofer())
"""

SLAM_LAUNCH = """
    import yaml
    from launch import LaunchDescription
    from launch.actions import DeclareLaunchArgument, OpaqueFunction
    from launch.substitutions import LaunchConfiguration
    from launch_ros.actions import Node


    def launch_setup(context):
        with open(LaunchConfiguration('gps_config').perform(context)) as file:
            config = yaml.safe_load(file)
        return [Node(package='rover_slam', executable=name, remappings=list(remaps.items()))
                for name, remaps in config['nodes'].items()]


    def generate_launch_description():
        return LaunchDescription([
            DeclareLaunchArgument('gps_config'),
            OpaqueFunction(function=launch_setup),
        ])
"""


#: The kalman_robot form: an ``OpaqueFunction`` whose list the analysis cannot determine (a helper
#: of an installed package decides between a node and a component).
HELPER_SLAM_LAUNCH = """
    from launch import LaunchDescription
    from launch.actions import OpaqueFunction
    from launch_ros.actions import Node
    from rover_utils.launch import node_or_component


    def launch_setup(context):
        description = node_or_component(context, package='rover_slam', executable='gps_preprocessor',
                                        remappings=[('fix', 'gps/fix'), ('fix/filtered', 'gps/fix/filtered')])
        description += [Node(package='rover_slam', executable='gps_spoofer',
                             remappings=[('fix/out', 'gps/fix')])]
        return description


    def generate_launch_description():
        return LaunchDescription([OpaqueFunction(function=launch_setup)])
"""


def slam_workspace(root: Path, fix: str, launch: str = SLAM_LAUNCH) -> Path:
    return write(root, {
        "rover_slam/package.xml": PACKAGE_XML.format(name="rover_slam", build="ament_python"),
        "rover_slam/setup.py": setup_py("rover_slam", "'gps_preprocessor = rover_slam.gps_preprocessor:main', "
                                                      "'gps_spoofer = rover_slam.gps_spoofer:main'"),
        "rover_slam/rover_slam/__init__.py": "",
        "rover_slam/rover_slam/gps_preprocessor.py": GPS_PREPROCESSOR.format(fix=fix),
        "rover_slam/rover_slam/gps_spoofer.py": GPS_SPOOFER,
        "rover_slam/launch/slam.launch.py": launch,
    })


def test_ends_a_launch_file_may_remap_unseen_are_not_dangling(tmp_path: Path) -> None:
    """kalman_robot: slam.launch.py's ``OpaqueFunction`` starts the GPS preprocessor and
    spoofer with remaps (``("fix", "gps/fix")``, ``("fix/out", "gps/fix")``) the analysis cannot
    see; their code-level names ``/fix``, ``/fix/out``, ``/fix/filtered`` looked like namespace
    slips of one another (15 false ROS001/ROS003 in kalman_slam and kalman_arm2). Here the
    launch file builds its nodes from a configuration file: executables and remaps unknown."""
    root = slam_workspace(tmp_path, "fix")
    assert findings(root, ["ROS001", "ROS003"]) == []


def test_a_slip_of_the_pen_in_such_a_package_is_still_reported(tmp_path: Path) -> None:
    """The twin: the preprocessor reads ``fix/ot``, a misspelling of the spoofer's ``fix/out``
    with its type; no remap makes a typo right."""
    root = slam_workspace(tmp_path, "fix/ot")
    assert [(code, path, line) for code, path, line, _ in findings(root, ["ROS001", "ROS003"])] == [
        ("ROS001", "rover_slam/rover_slam/gps_spoofer.py", 9),
        ("ROS003", "rover_slam/rover_slam/gps_preprocessor.py", 10)]


def test_ends_an_opaque_function_may_start_remapped_are_not_dangling(tmp_path: Path) -> None:
    """The same through an ``OpaqueFunction`` whose list of actions the analysis cannot
    determine: the launch file may start any node of its package, remapped."""
    root = slam_workspace(tmp_path, "fix", HELPER_SLAM_LAUNCH)
    assert findings(root, ["ROS001", "ROS003"]) == []


# -- ROS001 (power): a name a launch file makes unknown fills only gaps near it ------------------------
CMD_RELAY = """
    import rclpy
    from rclpy.node import Node
    from geometry_msgs.msg import Twist


    class CmdRelay(Node):
        def __init__(self):
            super().__init__('cmd_relay')
            self.declare_parameter('input_topic', 'cmd_vel_in')
            self.out = self.create_publisher(Twist, 'cmd_vel_out', 10)
            self.create_subscription(Twist, self.get_parameter('input_topic').value, self.out.publish, 10)


    def main():
        rclpy.init()
        rclpy.spin(CmdRelay())
"""

RELAY_LAUNCH = """
    from launch import LaunchDescription
    from launch.actions import DeclareLaunchArgument
    from launch.substitutions import LaunchConfiguration
    from launch_ros.actions import Node


    def generate_launch_description():
        return LaunchDescription([
            DeclareLaunchArgument('input'),
            Node(package='relay', executable='cmd_relay',
                 parameters=[{'input_topic': LaunchConfiguration('input')}]),
        ])
"""

ARM_DRIVER = """
    import rclpy
    from rclpy.node import Node
    from geometry_msgs.msg import Twist
    from std_msgs.msg import String


    class ArmDriver(Node):
        def __init__(self):
            super().__init__('arm_driver')
            self.state = self.create_publisher(String, '/arm/state', 10)
            self.velocity = self.create_publisher(Twist, '/arm_controler/commands', 10)
            self.create_subscription(String, '/arm/goal', self.on_goal, 10)

        def on_goal(self, msg):
            self.state.publish(msg)


    def main():
        rclpy.init()
        rclpy.spin(ArmDriver())
"""

ARM_GOALS = """
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import String


    def main():
        rclpy.init()
        node = Node('arm_goals')
        goal = node.create_publisher(String, '/arm/goal', 10)
        node.create_subscription(String, '/arm/state', lambda msg: goal.publish(msg), 10)
        rclpy.spin(node)
"""


def relay_workspace(root: Path, driver_package: str) -> Path:
    """``driver_package``: where the arm driver lives (``arm``: another package than the relay's)."""
    return write(root, {
        "relay/package.xml": PACKAGE_XML.format(name="relay", build="ament_python"),
        "relay/setup.py": setup_py("relay", "'cmd_relay = relay.cmd_relay:main'"),
        "relay/relay/__init__.py": "",
        "relay/relay/cmd_relay.py": CMD_RELAY,
        "relay/launch/relay.launch.py": RELAY_LAUNCH,
        f"{driver_package}/package.xml": PACKAGE_XML.format(name=driver_package, build="ament_python"),
        f"{driver_package}/{driver_package}/__init__.py": "",
        f"{driver_package}/{driver_package}/arm_driver.py": ARM_DRIVER,
        f"{driver_package}/{driver_package}/arm_goals.py": ARM_GOALS,
    })


def test_a_launch_argument_naming_one_input_does_not_excuse_another_package(tmp_path: Path) -> None:
    """adl-ros2 (seeded): a relay's input, named by a launch argument, could be any Twist
    topic; it excused the misspelt controller command of an arm driver in another package."""
    root = relay_workspace(tmp_path, "arm")
    assert [(code, path) for code, path, _, _ in findings(root, ["ROS001"])] == [
        ("ROS001", "arm/arm/arm_driver.py")]


def test_a_launch_argument_naming_an_input_may_fill_a_gap_of_its_package(tmp_path: Path) -> None:
    """The twin: in the relay's own package the unknown input may be the driver's output."""
    root = relay_workspace(tmp_path, "relay")
    assert findings(root, ["ROS001"]) == []


# -- ROS205 (power): an include of an installed package's launch file handed other values -------------
MOTOR_DRIVER = """
    import rclpy
    from rclpy.node import Node


    class MotorDriver(Node):
        def __init__(self):
            super().__init__('motor_driver')
            self.declare_parameter('i2c_bus', 1)
            self.declare_parameter('wheel_separation', 0.15)


    def main():
        rclpy.init()
        rclpy.spin(MotorDriver())
"""

MOTOR_YAML = """
    {section}:
      ros__parameters:
        i2c_bus: 5
        wheel_separation: 0.154
"""

TRACTOR_LAUNCH = """
    import os

    from ament_index_python.packages import get_package_share_directory
    from launch import LaunchDescription
    from launch.actions import IncludeLaunchDescription
    from launch.launch_description_sources import PythonLaunchDescriptionSource
    from launch_ros.actions import Node


    def generate_launch_description():
        config = os.path.join(get_package_share_directory('tractor'), 'config', 'motor.yaml')
        camera = IncludeLaunchDescription(
            PythonLaunchDescriptionSource(os.path.join(
                get_package_share_directory('realsense2_camera'), 'launch', 'rs_launch.py')),
            launch_arguments={{'enable_gyro': 'true', '{camera_argument}': {camera_value}}}.items())
        return LaunchDescription([
            camera,
            Node(package='tractor', executable='motor_driver', name='motor_driver', parameters=[config]),
        ])
"""


def tractor_workspace(root: Path, section: str, camera_argument: str = "depth_profile",
                      camera_value: str = "'848x100x100'") -> Path:
    return write(root, {
        "tractor/package.xml": PACKAGE_XML.format(name="tractor", build="ament_python"),
        "tractor/setup.py": setup_py("tractor", "'motor_driver = tractor.motor_driver:main'"),
        "tractor/tractor/__init__.py": "",
        "tractor/tractor/motor_driver.py": MOTOR_DRIVER,
        "tractor/config/motor.yaml": MOTOR_YAML.format(section=section),
        "tractor/launch/tractor.launch.py": TRACTOR_LAUNCH.format(
            camera_argument=camera_argument, camera_value=camera_value),
    })


def test_a_misspelt_section_beside_a_camera_include_is_reported(tmp_path: Path) -> None:
    """ros2-rover (seeded): every bring-up includes realsense2_camera's launch file, which the
    analysis does not follow; the include is handed camera settings only, so it cannot start a
    node with the motor file, and the misspelt section matches no node."""
    root = tractor_workspace(tmp_path, "motor_drive")
    assert [(code, path) for code, path, _, _ in findings(root, ["ROS205"])] == [
        ("ROS205", "tractor/config/motor.yaml")]


def test_a_correct_section_beside_a_camera_include_is_quiet(tmp_path: Path) -> None:
    root = tractor_workspace(tmp_path, "motor_driver")
    assert findings(root, ["ROS205"]) == []


def test_a_file_handed_to_an_include_not_followed_is_not_judged(tmp_path: Path) -> None:
    """The twin: the include is handed the file itself; its nodes may read any section."""
    root = tractor_workspace(tmp_path, "motor_drive", "config_file", "config")
    assert findings(root, ["ROS205"]) == []
