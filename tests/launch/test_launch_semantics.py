"""Issue 10 cause 5: launch semantics that made interfaces look like bugs or hid real ones.

Each test builds a small multi-file ament_python workspace (package.xml, setup.py with
console_scripts, modules importing each other) and runs the rules on the launched graph:
the bug, and the near-identical correct launch file that must stay quiet.
"""
from __future__ import annotations

import textwrap
from pathlib import Path

from flake8_rosgraph.launch.api import judged_graph
from flake8_rosgraph.rules import run_rules
from flake8_rosgraph.rules.base import RuleConfig

PACKAGE_XML = """<?xml version="1.0"?>
<package format="3"><name>{name}</name><version>0.1.0</version><description>d</description>
<maintainer email="dev@example.com">dev</maintainer><license>MIT</license>
<export><build_type>ament_python</build_type></export></package>
"""

SETUP_PY = """from setuptools import setup
setup(name='{name}', packages=['{name}'], entry_points={{'console_scripts': [
{scripts}]}})
"""

SENSORS = {
    "base.py": """
        from rclpy.node import Node


        class SensorBase(Node):
            '''Shared by the lidar and the camera executables.'''

            def __init__(self, name):
                super().__init__(name)
                self.declare_parameter('frame_id', 'base_link')
                self.status = self.create_publisher(DiagnosticStatus, '~/status', 10)


        from diagnostic_msgs.msg import DiagnosticStatus
        """,
    "lidar.py": """
        import rclpy
        from sensor_msgs.msg import LaserScan

        from drivers.base import SensorBase


        class Lidar(SensorBase):
            def __init__(self):
                super().__init__('lidar')
                self.declare_parameter('range_max', 10.0)
                self.scan = self.create_publisher(LaserScan, '/scan', 10)


        def main():
            rclpy.init()
            rclpy.spin(Lidar())
        """,
    "camera.py": """
        import rclpy
        from sensor_msgs.msg import Image

        from drivers.base import SensorBase


        class Camera(SensorBase):
            def __init__(self):
                super().__init__('camera')
                self.declare_parameter('exposure', 0.01)
                self.image = self.create_publisher(Image, 'image_raw', 10)


        def main():
            rclpy.init()
            rclpy.spin(Camera())
        """,
    "pair.py": """
        import rclpy
        from rclpy.executors import MultiThreadedExecutor
        from rclpy.node import Node
        from std_msgs.msg import String


        class Front(Node):
            def __init__(self):
                super().__init__('front')
                self.declare_parameter('gain', 1.0)
                self.pub = self.create_publisher(String, '/front/status', 10)


        class Back(Node):
            def __init__(self):
                super().__init__('back')
                self.declare_parameter('offset', 0.0)
                self.pub = self.create_publisher(String, '/back/status', 10)


        def main():
            rclpy.init()
            executor = MultiThreadedExecutor()
            for node in (Front(), Back()):
                executor.add_node(node)
            executor.spin()
        """,
}
SCRIPTS = ("lidar = drivers.lidar:main", "camera = drivers.camera:main", "pair = drivers.pair:main",
           "driver = drivers.driver:main", "mapper = drivers.mapper:main")


def workspace(tmp_path: Path, launch: dict[str, str], modules: dict[str, str] = SENSORS,
              extra: dict[str, str] | None = None) -> Path:
    pkg = tmp_path / "src" / "drivers"
    files = {"package.xml": PACKAGE_XML.format(name="drivers"),
             "setup.py": SETUP_PY.format(name="drivers",
                                         scripts="".join(f"    '{s}',\n" for s in SCRIPTS)),
             "resource/drivers": "", "drivers/__init__.py": ""}
    files.update({f"drivers/{name}": text for name, text in modules.items()})
    files.update({f"launch/{name}": text for name, text in launch.items()})
    files.update(extra or {})
    for rel, text in files.items():
        path = pkg / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(textwrap.dedent(text).lstrip())
    return tmp_path


def launch_py(*nodes: str) -> str:
    body = "".join(f"        {n},\n" for n in nodes)
    return ("from launch import LaunchDescription\nfrom launch_ros.actions import Node\n\n\n"
            "def generate_launch_description():\n    return LaunchDescription([\n"
            f"{body}    ])\n")


def findings(analyse, root: Path, codes: tuple[str, ...] = ("ROS2", "ROS0")) -> list[tuple[str, str, str]]:
    analysed = analyse(root)
    judged = judged_graph(analysed.graph, analysed.systems)
    return [(f.code, f.location.short(), f.message) for f in run_rules(judged, RuleConfig())
            if f.code.startswith(codes)]


def launched(analyse, root: Path, launch_file: str) -> list[tuple[str | None, str | None]]:
    analysed = analyse(root)
    system = analysed.system(launch_file)
    return sorted((i.node.fqn, i.code.cls) for i in system.instances)


LAUNCH = "src/drivers/launch/"


# -- a base class shared by two executables -------------------------------------------------------

def test_launching_one_subclass_does_not_start_its_siblings(tmp_path, analyse_root):
    root = workspace(tmp_path, {"lidar.launch.py": launch_py(
        "Node(package='drivers', executable='lidar', name='scanner', "
        "parameters=[{'range_max': 30.0, 'frame_id': 'laser'}])")})
    assert launched(analyse_root, root, "lidar.launch.py") == [("/scanner", "Lidar")]
    assert findings(analyse_root, root, ("ROS2",)) == []


def test_a_parameter_of_the_sibling_class_is_still_unknown(tmp_path, analyse_root):
    root = workspace(tmp_path, {"lidar.launch.py": launch_py(
        "Node(package='drivers', executable='lidar', parameters=[{'exposure': 0.02}])")})
    assert findings(analyse_root, root, ("ROS2",)) == [
        ("ROS204", LAUNCH + "lidar.launch.py:7",
         "parameter 'exposure' is set for node '/lidar', which never declares it")]


# -- ROS204 judges a process ----------------------------------------------------------------------

def test_inline_parameters_reach_every_node_of_the_process(tmp_path, analyse_root):
    root = workspace(tmp_path, {"pair.launch.py": launch_py(
        "Node(package='drivers', executable='pair', parameters=[{'gain': 2.0, 'offset': 0.5}])")})
    assert findings(analyse_root, root, ("ROS2",)) == []


def test_a_parameter_no_node_of_the_process_declares(tmp_path, analyse_root):
    root = workspace(tmp_path, {"pair.launch.py": launch_py(
        "Node(package='drivers', executable='pair', parameters=[{'gain': 2.0, 'ofset': 0.5}])")})
    assert findings(analyse_root, root, ("ROS2",)) == [
        ("ROS204", LAUNCH + "pair.launch.py:7",
         "parameter 'ofset' is set for nodes '/back', '/front', none of which declares it; "
         "did you mean 'offset'?")]


# -- ROS204 and shared parameter files -----------------------------------------------------------

SHARED_YAML = """
    /**:
      ros__parameters:
        frame_id: base_footprint
        range_max: 25.0
        exposure: 0.02
        course_name: figure_eight
        {extra}
    """


def _shared(tmp_path: Path, extra: str = "", *more: str) -> Path:
    return workspace(tmp_path, {"sensors.launch.py": launch_py(
        "Node(package='drivers', executable='lidar', parameters=['src/drivers/config/shared.yaml'])",
        "Node(package='drivers', executable='camera', parameters=['src/drivers/config/shared.yaml'])",
        *more)}, extra={"config/shared.yaml": SHARED_YAML.format(extra=extra)})


def test_a_shared_section_reaches_nodes_that_each_declare_part_of_it(tmp_path, analyse_root):
    # 'course_name' is read by the launch file or another tool: no node of it is near it.
    assert findings(analyse_root, _shared(tmp_path), ("ROS2",)) == []


def test_a_near_miss_in_a_shared_section_is_reported_once(tmp_path, analyse_root):
    assert findings(analyse_root, _shared(tmp_path, "exposur: 0.03"), ("ROS2",)) == [
        ("ROS204", "src/drivers/config/shared.yaml:7",
         "parameter 'exposur' is set for nodes '/camera', '/lidar', none of which declares it; "
         "did you mean 'exposure'?")]


def test_a_setting_that_also_reaches_a_node_without_code_is_not_judged(tmp_path, analyse_root):
    real = "Node(package='gripper_driver', executable='gripper_node', name='gripper', " \
           "parameters=['src/drivers/config/gripper.yaml'], condition=UnlessCondition('false'))"
    fake = "Node(package='drivers', executable='lidar', name='gripper', " \
           "parameters=['src/drivers/config/gripper.yaml'])"
    files = {"config/gripper.yaml": "gripper:\n  ros__parameters:\n    grasp_force: 20.0\n"}
    imports = "from launch.conditions import UnlessCondition\n"
    # the file also configures the installed (C++) driver, which the analysis cannot see
    root = workspace(tmp_path, {"gripper.launch.py": imports + launch_py(real, fake)}, extra=files)
    assert findings(analyse_root, root, ("ROS2",)) == []
    root = workspace(tmp_path / "alone", {"gripper.launch.py": launch_py(fake)}, extra=files)
    assert findings(analyse_root, root, ("ROS2",)) == [
        ("ROS204", "src/drivers/config/gripper.yaml:3",
         "parameter 'grasp_force' is set for node '/gripper', which never declares it")]


# -- ROS007 and conditions the analysis does not evaluate -----------------------------------------

EXPRESSION = ("from launch.conditions import IfCondition, UnlessCondition\n"
              "from launch.substitutions import LaunchConfiguration, PythonExpression\n")


def test_if_and_unless_of_one_python_expression_never_run_together(tmp_path, analyse_root):
    stream = "PythonExpression([LaunchConfiguration('stream')])"
    root = workspace(tmp_path, {"scan.launch.py": EXPRESSION + launch_py(
        f"Node(package='drivers', executable='lidar', name='scanner', condition=IfCondition({stream}))",
        f"Node(package='drivers', executable='camera', name='scanner', condition=UnlessCondition({stream}))")})
    assert findings(analyse_root, root, ("ROS007",)) == []


def test_conditions_on_two_python_expressions_may_both_hold(tmp_path, analyse_root):
    root = workspace(tmp_path, {"scan.launch.py": EXPRESSION + launch_py(
        "Node(package='drivers', executable='lidar', name='scanner', "
        "condition=IfCondition(PythonExpression([LaunchConfiguration('stream')])))",
        "Node(package='drivers', executable='camera', name='scanner', "
        "condition=UnlessCondition(PythonExpression([LaunchConfiguration('record')])))")})
    assert [code for code, _, _ in findings(analyse_root, root, ("ROS007",))] == ["ROS007", "ROS007"]


EVAL_XML = """<launch>
  <arg name="vehicle_model" default=""/>
  <group if="$(eval '&quot;$(var vehicle_model)&quot; {first} &quot;&quot;')">
    <node pkg="drivers" exec="lidar" name="analyzer"/>
  </group>
  <group if="$(eval '&quot;$(var vehicle_model)&quot; {second} &quot;&quot;')">
    <node pkg="drivers" exec="camera" name="analyzer"/>
  </group>
</launch>
"""


def test_one_comparison_with_eq_and_ne_never_runs_together(tmp_path, analyse_root):
    root = workspace(tmp_path, {"analyzer.launch.xml": EVAL_XML.format(first="!=", second="==")})
    assert findings(analyse_root, root, ("ROS007",)) == []
    # the twin: the same comparison twice holds for both
    root = workspace(tmp_path / "same", {"analyzer.launch.xml": EVAL_XML.format(first="==", second="==")})
    assert [code for code, _, _ in findings(analyse_root, root, ("ROS007",))] == ["ROS007", "ROS007"]


# -- ROS202 and private remaps --------------------------------------------------------------------

def test_a_private_remap_that_matches_nothing(tmp_path, analyse_root):
    root = workspace(tmp_path, {"lidar.launch.py": launch_py(
        "Node(package='drivers', executable='lidar', remappings=[('~/stats', '/diagnostics/lidar')])")})
    found = findings(analyse_root, root, ("ROS2",))
    assert [(code, where) for code, where, _ in found] == [("ROS202", LAUNCH + "lidar.launch.py:7")]
    assert found[0][2].startswith("remap '~/stats' -> '/diagnostics/lidar' matches no name node '/lidar'")


def test_a_private_remap_that_matches_the_private_name(tmp_path, analyse_root):
    root = workspace(tmp_path, {"lidar.launch.py": launch_py(
        "Node(package='drivers', executable='lidar', remappings=[('~/status', '/diagnostics/lidar')])",
        "Node(package='drivers', executable='camera', remappings=[('~/get_parameters', 'params')])")})
    assert findings(analyse_root, root, ("ROS2",)) == []


# -- launch names and absolute topics -------------------------------------------------------------

def test_an_invalid_launch_name_is_reported_at_the_launch_file_only(tmp_path, analyse_root):
    root = workspace(tmp_path, {"lidar.launch.py": launch_py(
        "Node(package='drivers', executable='lidar', name='front-lidar')")})
    found = findings(analyse_root, root)
    assert [(code, where) for code, where, _ in found] == [("ROS203", LAUNCH + "lidar.launch.py:7")]


CAMERA_GROUP = """
    from launch import LaunchDescription
    from launch.actions import DeclareLaunchArgument, GroupAction
    from launch.substitutions import LaunchConfiguration
    from launch_ros.actions import Node, PushRosNamespace


    def generate_launch_description():
        camera = GroupAction([
            PushRosNamespace(LaunchConfiguration('camera_name')),
            Node(package='drivers', executable='camera', name='driver', namespace={namespace}),
        ])
        return LaunchDescription([DeclareLaunchArgument('camera_name', default_value='camera'), camera])
    """


def test_an_empty_namespace_under_a_pushed_one_runs_in_the_pushed_one(tmp_path, analyse_root):
    """launch_ros strips the trailing '/' of ``'/camera' + '/' + ''`` (and of ``'/camera/'``): the
    camera driver runs as ``/camera/driver``, not in the invalid namespace ``/camera/`` (an
    Orbbec camera's 40 launch files, each reported)."""
    for namespace in ("''", "'/camera/'"):
        launch = {"camera.launch.py": CAMERA_GROUP.format(namespace=namespace)}
        root = workspace(tmp_path / namespace.strip("'/"), launch)
        assert launched(analyse_root, root, "camera.launch.py") == [("/camera/driver", "Camera")]
        assert findings(analyse_root, root, ("ROS203",)) == []


def test_an_invalid_namespace_under_a_pushed_one_is_still_reported(tmp_path, analyse_root):
    root = workspace(tmp_path, {"camera.launch.py": CAMERA_GROUP.format(namespace="'front cam'")})
    assert [code for code, _, _ in findings(analyse_root, root, ("ROS203",))] == ["ROS203"]


LOCALIZATION = """
    from launch import LaunchDescription
    from launch.actions import DeclareLaunchArgument, LogInfo, OpaqueFunction
    from launch.substitutions import LaunchConfiguration
    from launch_ros.actions import Node


    def launch_setup(context):
        map_server = Node(package='nav2_map_server', executable='map_server', name='map_server',
                          namespace='')
        actions = [map_server]
        if LaunchConfiguration('use_slam').perform(context) == 'true':
            actions.extend([Node(package='slam_toolbox', executable='localization_slam_toolbox_node',
                                 name='slam_toolbox')])
        else:
            actions.extend([LogInfo(msg='static map->odom'),
                            Node(package='nav2_map_server', executable='map_server', name={second},
                                 namespace='')])
        return actions


    def generate_launch_description():
        return LaunchDescription([DeclareLaunchArgument('use_slam', default_value='true'),
                                  OpaqueFunction(function=launch_setup)])
    """


def test_an_action_both_branches_of_a_launch_function_return_starts_once(tmp_path, analyse_root):
    """The map server both lists of a launch function hold (one per branch of its ``if``) is
    one action: it was started once per list, and reported as a duplicate of itself."""
    root = workspace(tmp_path, {"localization.launch.py": LOCALIZATION.format(second="'odom_tf'")})
    assert findings(analyse_root, root, ("ROS007",)) == []
    started = [n.name for n in analyse_root(root).system("localization.launch.py").nodes]
    assert sorted(started) == ["map_server", "odom_tf", "slam_toolbox"]


def test_a_second_action_of_the_same_name_in_one_branch_is_still_reported(tmp_path, analyse_root):
    root = workspace(tmp_path, {"localization.launch.py": LOCALIZATION.format(
        second="'map_server'")})
    assert [code for code, _, _ in findings(analyse_root, root, ("ROS007",))] == ["ROS007"]


# -- arguments an include passes but the analysis cannot read -------------------------------------

INCLUDED = """
    from launch import LaunchDescription
    from launch.substitutions import LaunchConfiguration
    from launch_ros.actions import Node


    def generate_launch_description():
        return LaunchDescription([
            Node(package='drivers', executable=LaunchConfiguration('driver', default='TODO')),
        ])
    """


def including(arguments: str) -> str:
    return textwrap.dedent(f"""
        import os

        from launch import LaunchDescription
        from launch.actions import IncludeLaunchDescription
        from launch.launch_description_sources import PythonLaunchDescriptionSource
        from launch.substitutions import PathJoinSubstitution
        from launch_ros.substitutions import FindPackageShare


        def generate_launch_description():
            driver = PathJoinSubstitution([FindPackageShare('drivers'), 'launch', 'driver.launch.py'])
            return LaunchDescription([
                IncludeLaunchDescription(PythonLaunchDescriptionSource(driver),
                                         launch_arguments={arguments}),
            ])
        """)


def test_an_unreadable_include_argument_is_unknown_not_the_placeholder(tmp_path, analyse_root):
    root = workspace(tmp_path, {
        "driver.launch.py": INCLUDED,
        "robot.launch.py": including("{key: value for key, value in os.environ.items()}.items()")})
    analysed = analyse_root(root)
    [node] = analysed.system("robot.launch.py").nodes
    assert (node.executable, node.target.status) == (None, "unknown")
    assert node.unresolved == ["executable: launch argument 'driver' comes from an include "
                               "whose arguments are unknown"]
    # launched alone, the file does start its placeholder: that is reported
    [alone] = analysed.system("driver.launch.py").nodes
    assert (alone.executable, alone.target.status) == ("TODO", "missing-executable")


def test_a_readable_include_argument_replaces_the_default(tmp_path, analyse_root):
    root = workspace(tmp_path, {
        "driver.launch.py": INCLUDED,
        "robot.launch.py": including("{'driver': 'lidar'}.items()")})
    [node] = analyse_root(root).system("robot.launch.py").nodes
    assert (node.executable, node.target.status) == ("lidar", "found")


# -- ROS205 unmatched-parameter-section -----------------------------------------------------------

SENSOR_PARAMS = """
    /**:
      ros__parameters:
        frame_id: sensor_link
    robot:
      front_lidar:
        ros__parameters:
          range_max: 25.0
    /robot/*_camera:
      ros__parameters:
        exposure: 0.02
    lidar:
      ros__parameters:
        range_max: 12.0
    """

SENSORS_LAUNCH = """
    import os

    from ament_index_python.packages import get_package_share_directory
    from launch import LaunchDescription
    from launch_ros.actions import Node


    def generate_launch_description():
        params = os.path.join(get_package_share_directory('drivers'), 'config', 'sensors.yaml')
        return LaunchDescription([
            Node(package='drivers', executable='lidar', name={lidar}, namespace='robot',
                 parameters=[params]),
            Node(package='drivers', executable='camera', name='rear_camera', namespace='robot',
                 parameters=[params]),
        ])
    """


def sensors(tmp_path: Path, lidar: str, **launch: str) -> Path:
    return workspace(tmp_path, {"sensors.launch.py": SENSORS_LAUNCH.format(lidar=lidar), **launch},
                     extra={"config/sensors.yaml": SENSOR_PARAMS})


def test_a_section_no_started_node_matches(tmp_path, analyse_root):
    root = sensors(tmp_path, "'front_lidar'")
    assert findings(analyse_root, root, ("ROS205",)) == [
        ("ROS205", "src/drivers/config/sensors.yaml:11",
         "parameter section '/lidar' matches no node started with this file "
         "(/robot/front_lidar, /robot/rear_camera): its 1 value is ignored")]


def test_a_section_another_launch_file_uses_is_matched(tmp_path, analyse_root):
    root = sensors(tmp_path, "'front_lidar'", **{"bench.launch.py": launch_py(
        "Node(package='drivers', executable='lidar', "
        "parameters=[PathJoinSubstitution([FindPackageShare('drivers'), 'config', 'sensors.yaml'])])"
    ).replace("from launch_ros.actions import Node\n",
              "from launch.substitutions import PathJoinSubstitution\n"
              "from launch_ros.actions import Node\nfrom launch_ros.substitutions import FindPackageShare\n")})
    assert findings(analyse_root, root, ("ROS205",)) == []


def test_a_node_name_the_analysis_cannot_know_keeps_the_file_quiet(tmp_path, analyse_root):
    root = sensors(tmp_path, "LaunchConfiguration('lidar_name')")
    launch = root / "src/drivers/launch/sensors.launch.py"
    launch.write_text(launch.read_text().replace(
        "from launch_ros.actions import Node\n",
        "from launch.substitutions import LaunchConfiguration\nfrom launch_ros.actions import Node\n"))
    assert findings(analyse_root, root, ("ROS205",)) == []


def test_a_launch_file_not_followed_completely_keeps_its_files_quiet(tmp_path, analyse_root):
    root = sensors(tmp_path, "'front_lidar'")
    launch = root / "src/drivers/launch/sensors.launch.py"
    launch.write_text(launch.read_text().replace(
        "    ])\n",
        "        OpaqueFunction(function=pairs_for, kwargs={'params': params}),\n"
        "    ])\n").replace("from launch import LaunchDescription\n",
                             "from launch import LaunchDescription\nfrom launch.actions import OpaqueFunction\n"
                             "from sensor_tools.launching import pairs_for  # not in the workspace\n"))
    assert findings(analyse_root, root, ("ROS205",)) == []


# -- a launch file that starts one driver is not a closed system ----------------------------------

ROBOT = {
    "driver.py": """
        import rclpy
        from nav_msgs.msg import Odometry
        from rclpy.node import Node
        from sensor_msgs.msg import LaserScan


        class Driver(Node):
            def __init__(self):
                super().__init__('driver')
                self.odom = self.create_publisher(Odometry, '/odom', 10)
                self.scan = self.create_publisher(LaserScan, 'scan', 10)


        def main():
            rclpy.init()
            rclpy.spin(Driver())
        """,
    "mapper.py": """
        import rclpy
        from nav_msgs.msg import Odometry
        from rclpy.node import Node
        from sensor_msgs.msg import LaserScan


        class Mapper(Node):
            def __init__(self):
                super().__init__('mapper')
                self.create_subscription(Odometry, '/odom', self.on_odom, 10)
                self.create_subscription(LaserScan, 'scan', self.on_scan, 10)

            def on_odom(self, msg):
                self.get_logger().info('odom')

            def on_scan(self, msg):
                self.get_logger().info('scan')


        def main():
            rclpy.init()
            rclpy.spin(Mapper())
        """,
}


def robot(tmp_path: Path, launch: dict[str, str]) -> Path:
    return workspace(tmp_path, launch, modules=ROBOT)


def test_a_driver_launched_alone_in_a_namespace_keeps_its_outputs_as_interfaces(tmp_path, analyse_root):
    root = robot(tmp_path, {"driver.launch.py": launch_py(
        "Node(package='drivers', executable='driver', namespace='robot')")})
    assert findings(analyse_root, root, ("ROS0",)) == []


def test_a_typo_between_nodes_of_one_launched_system_is_still_reported(tmp_path, analyse_root):
    modules = dict(ROBOT, **{"mapper.py": ROBOT["mapper.py"].replace("'scan'", "'scna'")})
    root = workspace(tmp_path, {"robot.launch.py": launch_py(
        "Node(package='drivers', executable='driver', namespace='robot')",
        "Node(package='drivers', executable='mapper', namespace='robot')")}, modules=modules)
    assert [(code, where) for code, where, _ in findings(analyse_root, root, ("ROS0",))] == [
        ("ROS001", "src/drivers/drivers/driver.py:11"), ("ROS003", "src/drivers/drivers/mapper.py:11")]


def test_a_typo_the_launch_file_does_not_rename_is_still_reported(tmp_path, analyse_root):
    modules = dict(ROBOT, **{"mapper.py": ROBOT["mapper.py"].replace("'scan'", "'scna'")})
    root = workspace(tmp_path, {"driver.launch.py": launch_py(
        "Node(package='drivers', executable='driver')")}, modules=modules)
    found = findings(analyse_root, root, ("ROS0",))
    assert [(code, where) for code, where, _ in found] == [
        ("ROS001", "src/drivers/drivers/driver.py:11"), ("ROS003", "src/drivers/drivers/mapper.py:11")]
