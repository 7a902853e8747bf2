"""Extraction mechanisms found on real repositories outside every test set, on realistic
multi-file packages: each follows what the code does at run time, and a near-identical twin
where following it must not invent a name or an entity."""
from __future__ import annotations

from pathlib import Path

from flake8_rosgraph.analysis import analyse, build_graph
from flake8_rosgraph.explain import explain

from test_workspace_discovery import PACKAGE_XML, write


def entities(root: Path, kinds: tuple[str, ...] = ("publishers", "subscriptions", "services")
             ) -> dict[str | None, list[tuple[str, str]]]:
    """Each node's entities of ``kinds`` as ``(kind, name or "?")``."""
    return {node.fqn: sorted((e.kind, e.name or "?") for e in node.entities if e.kind in kinds)
            for node in build_graph(root).nodes}


def explained(root: Path) -> list[tuple[str, int, str]]:
    graph, analysis = analyse(root)
    return [(e.site.path, e.site.line, e.status) for e in explain(analysis, graph).explanations]


CMAKE = """
    cmake_minimum_required(VERSION 3.8)
    project({name})
    find_package(ament_cmake REQUIRED)
    install(PROGRAMS
      scripts/{first}.py
      scripts/{second}.py
      scripts/calibration_base.py
      DESTINATION lib/${{PROJECT_NAME}})
    ament_package()
"""

# -- scripts importing the module beside them --------------------------------------------------
CALIBRATION_BASE = """
    from nav_msgs.msg import Odometry
    from rclpy.node import Node
    from std_msgs.msg import Float32


    class CalibrationBase(Node):
        '''Shared by every calibration script: odometry in, progress out.'''

        def __init__(self, node_name):
            super().__init__(node_name)
            self.odom_sub = self.create_subscription(Odometry, '/localization/odom',
                                                     self.on_odom, 10)
            self.progress_pub = self.create_publisher(Float32, '~/progress', 1)

        def on_odom(self, msg):
            self.last_odom = msg
"""

CALIBRATION = {
    "calibration/package.xml": PACKAGE_XML.format(name="calibration", build="ament_cmake"),
    "calibration/CMakeLists.txt": CMAKE.format(name="calibration", first="steer_calibrator",
                                               second="brake_calibrator"),
    # An __init__.py in scripts/ (for a linter): the scripts still run as programs.
    "calibration/scripts/__init__.py": "",
    "calibration/scripts/calibration_base.py": CALIBRATION_BASE,
    "calibration/scripts/steer_calibrator.py": """
        #!/usr/bin/env python3
        from calibration_base import CalibrationBase
        import rclpy
        from std_msgs.msg import Float64


        class SteerCalibrator(CalibrationBase):
            def __init__(self):
                super().__init__('steer_calibrator')
                self.cmd_pub = self.create_publisher(Float64, '/vehicle/steer_cmd', 10)


        def main():
            rclpy.init()
            rclpy.spin(SteerCalibrator())


        if __name__ == '__main__':
            main()
    """,
    "calibration/scripts/brake_calibrator.py": """
        #!/usr/bin/env python3
        import calibration_base
        import rclpy
        from std_msgs.msg import Float64


        class BrakeCalibrator(calibration_base.CalibrationBase):
            def __init__(self):
                super().__init__('brake_calibrator')
                self.cmd_pub = self.create_publisher(Float64, '/vehicle/brake_cmd', 10)


        if __name__ == '__main__':
            rclpy.init()
            rclpy.spin(BrakeCalibrator())
    """,
}


def test_a_script_imports_the_module_beside_it(tmp_path: Path) -> None:
    """A script run as a program has its folder first on ``sys.path``: ``from
    calibration_base import …`` and ``import calibration_base`` reach the file beside it, so
    each node gets its own name and the base class's entities (autoware_tools'
    control_data_collecting_tool: 28 sites on nodes of unknown name before)."""
    root = write(tmp_path, CALIBRATION)
    assert entities(root) == {
        "/brake_calibrator": [("publishers", "/brake_calibrator/progress"),
                              ("publishers", "/vehicle/brake_cmd"),
                              ("subscriptions", "/localization/odom")],
        "/steer_calibrator": [("publishers", "/steer_calibrator/progress"),
                              ("publishers", "/vehicle/steer_cmd"),
                              ("subscriptions", "/localization/odom")],
    }
    assert all(status == "complete" for _, _, status in explained(root))


def test_a_folder_without_init_beside_the_scripts_is_a_namespace_package(tmp_path: Path) -> None:
    """``from courses.load_course import …`` in a script reaches ``courses/load_course.py``
    beside it, and that module's own ``from courses.markers import …`` reaches its neighbour
    (the program's folder is on ``sys.path``), so the course's publisher is on the node
    (autoware_tools: the course parameters of data_collecting_trajectory_publisher)."""
    files = dict(CALIBRATION)
    files["calibration/scripts/courses/load_course.py"] = """
        from courses.markers import add_marker_publisher


        def declare_course(node, course):
            node.declare_parameter('course_name', course)
            add_marker_publisher(node)
    """
    files["calibration/scripts/courses/markers.py"] = """
        from visualization_msgs.msg import MarkerArray


        def add_marker_publisher(node):
            return node.create_publisher(MarkerArray, '~/course_markers', 1)
    """
    files["calibration/scripts/steer_calibrator.py"] = files[
        "calibration/scripts/steer_calibrator.py"].replace(
        "from calibration_base import CalibrationBase",
        "from calibration_base import CalibrationBase\n"
        "        from courses.load_course import declare_course").replace(
        "self.cmd_pub = self.create_publisher(Float64, '/vehicle/steer_cmd', 10)",
        "self.cmd_pub = self.create_publisher(Float64, '/vehicle/steer_cmd', 10)\n"
        "                declare_course(self, 'eight')")
    got = entities(write(tmp_path, files))
    assert ("publishers", "/steer_calibrator/course_markers") in got["/steer_calibrator"]
    assert ("publishers", "/brake_calibrator/course_markers") not in got["/brake_calibrator"]


def test_same_named_scripts_of_two_packages_import_their_own_neighbour(tmp_path: Path) -> None:
    """Two packages ship a ``calibration_base.py`` beside their scripts: each script gets the
    one in its own folder, not whichever file the workspace walk met first."""
    files = dict(CALIBRATION)
    files.update({
        "lateral/package.xml": PACKAGE_XML.format(name="lateral", build="ament_cmake"),
        "lateral/CMakeLists.txt": CMAKE.format(name="lateral", first="yaw_calibrator",
                                               second="yaw_calibrator"),
        "lateral/scripts/calibration_base.py": CALIBRATION_BASE.replace(
            "/localization/odom", "/lateral/odom"),
        "lateral/scripts/yaw_calibrator.py": """
            #!/usr/bin/env python3
            from calibration_base import CalibrationBase
            import rclpy


            def main():
                rclpy.init()
                rclpy.spin(CalibrationBase('yaw_calibrator'))
        """,
    })
    got = entities(write(tmp_path, files))
    assert got["/yaw_calibrator"] == [("publishers", "/yaw_calibrator/progress"),
                                      ("subscriptions", "/lateral/odom")]
    assert ("subscriptions", "/localization/odom") in got["/steer_calibrator"]


def test_a_package_module_keeps_the_workspace_module_of_that_name(tmp_path: Path) -> None:
    """Inside an ament_python package, ``from topics import …`` means the workspace's top-level
    ``topics`` module (the one Python finds on ``sys.path``), not a ``topics.py`` that happens
    to sit beside the importing module: that file must not rename anything."""
    files = {
        "common/package.xml": PACKAGE_XML.format(name="common", build="ament_python"),
        "common/setup.py": "from setuptools import setup\nsetup(name='common', py_modules=['topics'])\n",
        "common/topics.py": "ODOM = 'odom'\n",
        "rover/package.xml": PACKAGE_XML.format(name="rover", build="ament_python"),
        "rover/rover/__init__.py": "",
        "rover/rover/topics.py": "ODOM = 'wheel_odom_unused'\n",
        "rover/rover/driver.py": """
            import rclpy
            from rclpy.node import Node
            from nav_msgs.msg import Odometry
            from topics import ODOM
            import missing_helper


            class Driver(Node):
                def __init__(self):
                    super().__init__('driver')
                    self.create_publisher(Odometry, ODOM, 10)
                    self.create_publisher(Odometry, missing_helper.TOPIC, 10)


            def main():
                rclpy.init()
                rclpy.spin(Driver())
        """,
    }
    assert entities(write(tmp_path, files)) == {
        "/driver": [("publishers", "/odom"), ("publishers", "?")]}


# -- a dict only ever seen empty, filled through an alias ----------------------------------------
SWARM_SERVER = """
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import String
    from std_srvs.srv import Empty

    import radio_link


    class SwarmServer(Node):
        def __init__(self):
            super().__init__('swarm_server', automatically_declare_parameters_from_overrides=True)
            self.params = self.to_tree(self._parameters)
            self.names = {'all': 'all'}
            robots = self.params['robots']
            for robot in robots:
                if robots[robot]['enabled']:
                    self.names[robots[robot]['uri']] = robot
            self.link = radio_link.Swarm()
            self.link.connected.add_callback(self.on_connected)

        def to_tree(self, flat):
            '''{'robots.cf1.uri': …} -> {'robots': {'cf1': {'uri': …}}}'''
            tree = {}
            for key in flat:
                level = tree
                for part in key.split('.')[:-1]:
                    level = level.setdefault(part, {})
                level[key.split('.')[-1]] = flat[key].value
            return tree

        def on_connected(self, uri):
            for uri in self.names:
                if uri == 'all':
                    continue
                name = self.names[uri]
                self.create_publisher(String, name + '/status', 10)
                self.create_service(Empty, name + '/emergency', self.on_emergency)
            self.create_service(Empty, 'all/emergency', self.on_emergency)

        def on_emergency(self, request, response):
            return response


    def main():
        rclpy.init()
        rclpy.spin(SwarmServer())
"""


def test_a_dict_filled_through_an_alias_is_not_a_dead_end(tmp_path: Path) -> None:
    """``tree`` is filled only through ``level`` (an alias), so the analysis sees it empty;
    reading ``tree['robots'][robot]`` must be unknown, not a KeyError that makes the rest of
    ``__init__`` and every per-robot entity unreachable (crazyswarm2's server: 15 sites
    "never reached" before). The per-robot names come from parameters: unknown, with their
    suffix; no name is made up for sure from the ``'all'`` entry the loop skips (the analysis
    does not tie the skipped key to its value, so ``/all/status`` is only a partly known name
    beside the unknown one, as ``name`` itself is)."""
    root = write(tmp_path, {
        "swarm/package.xml": PACKAGE_XML.format(name="swarm", build="ament_python"),
        "swarm/swarm/__init__.py": "",
        "swarm/swarm/server.py": SWARM_SERVER,
    })
    graph = build_graph(root)
    (node,) = graph.nodes
    got = sorted((e.kind, e.name or "?", e.name_text) for e in node.entities
                 if e.kind in ("publishers", "services"))
    assert got == [("publishers", "/all/status", "name + '/status'"),
                   ("publishers", "?", "name + '/status'"),
                   ("services", "/all/emergency", "'all/emergency'"),
                   ("services", "/all/emergency", "name + '/emergency'"),
                   ("services", "?", "name + '/emergency'")]
    assert {(e.name, e.name_text) for e in node.entities if e.partial} == {
        ("/all/status", "name + '/status'"), ("/all/emergency", "name + '/emergency'")}


def test_a_table_written_where_it_is_made_still_decides_its_lookups(tmp_path: Path) -> None:
    """The twin: a table the analysis sees filled where it is made (empty only before the loop
    that fills it) names exactly its entries: the empty first state adds no unknown."""
    root = write(tmp_path, {
        "fleet/package.xml": PACKAGE_XML.format(name="fleet", build="ament_python"),
        "fleet/fleet/__init__.py": "",
        "fleet/fleet/relay.py": """
            import rclpy
            from rclpy.node import Node
            from std_msgs.msg import String

            ROBOTS = {'scout': 'radio://0/80', 'hauler': 'radio://0/90'}


            class Relay(Node):
                def __init__(self):
                    super().__init__('relay')
                    links = {}
                    for name in ROBOTS:
                        links[name] = ROBOTS[name]
                    for name in links:
                        self.create_publisher(String, name + '/status', 10)


            def main():
                rclpy.init()
                rclpy.spin(Relay())
        """,
    })
    assert entities(root) == {"/relay": [("publishers", "/hauler/status"),
                                         ("publishers", "/scout/status")]}


# -- launch: a description chosen among several; a parameter file shared by several nodes --------
LIDAR_DRIVER = """
    import rclpy
    from rclpy.node import Node
    from sensor_msgs.msg import LaserScan


    class LidarDriver(Node):
        def __init__(self):
            super().__init__('lidar_driver')
            rate = self.declare_parameter('rate', 10.0).value
            self.frame = self.declare_parameter('frame_id', 'laser').value
            self.pub = self.create_publisher(LaserScan, 'scan', 10)
            self.timer = self.create_timer(1.0 / rate, self.tick)

        def tick(self):
            self.pub.publish(LaserScan())


    def main():
        rclpy.init()
        rclpy.spin(LidarDriver())
"""

SCAN_MONITOR = """
    import rclpy
    from rclpy.node import Node
    from sensor_msgs.msg import LaserScan


    class ScanMonitor(Node):
        def __init__(self):
            super().__init__('scan_monitor')
            self.declare_parameter('timeout', 1.0)
            self.create_subscription(LaserScan, 'scan', self.on_scan, 10)

        def on_scan(self, msg):
            pass


    def main():
        rclpy.init()
        rclpy.spin(ScanMonitor())
"""

LIDAR_SETUP = """
    from setuptools import setup

    setup(
        name='lidar_driver',
        packages=['lidar_driver'],
        entry_points={'console_scripts': [
            'driver = lidar_driver.driver:main',
            'monitor = lidar_driver.monitor:main',
        ]},
    )
"""

#: Which stack runs depends on the environment: one of two descriptions is returned.
CHOSEN_LAUNCH = """
    import os

    from launch import LaunchDescription
    from launch.substitutions import PathJoinSubstitution
    from launch_ros.actions import Node
    from launch_ros.substitutions import FindPackageShare


    def generate_launch_description():
        params = PathJoinSubstitution([FindPackageShare('robot_bringup'), 'config', 'common.yaml'])
        if os.environ.get('LIDAR_MODE', 'single') == 'single':
            return LaunchDescription([
                Node(package='lidar_driver', executable='driver', name='lidar', parameters=[params]),
                Node(package='lidar_driver', executable='monitor', parameters=[params]),
            ])
        return LaunchDescription([
            Node(package='lidar_driver', executable='driver', name='lidar', parameters=[params]),
            Node(package='lidar_driver', executable='monitor', parameters=[params]),
            Node(package='lidar_driver', executable='monitor', name='rear_monitor',
                 parameters=[params]),
        ])
"""

#: One description: the second driver really runs beside the first under the same name.
ONE_LAUNCH = """
    from launch import LaunchDescription
    from launch.substitutions import PathJoinSubstitution
    from launch_ros.actions import Node
    from launch_ros.substitutions import FindPackageShare


    def generate_launch_description():
        params = PathJoinSubstitution([FindPackageShare('robot_bringup'), 'config', 'common.yaml'])
        return LaunchDescription([
            Node(package='lidar_driver', executable='driver', name='lidar', parameters=[params]),
            Node(package='lidar_driver', executable='monitor', parameters=[params]),
            Node(package='lidar_driver', executable='driver', name='lidar', parameters=[params]),
        ])
"""


def lidar_workspace(root: Path, launch: str, config: str) -> Path:
    return write(root, {
        "src/lidar_driver/package.xml": PACKAGE_XML.format(name="lidar_driver",
                                                           build="ament_python"),
        "src/lidar_driver/setup.py": LIDAR_SETUP,
        "src/lidar_driver/lidar_driver/__init__.py": "",
        "src/lidar_driver/lidar_driver/driver.py": LIDAR_DRIVER,
        "src/lidar_driver/lidar_driver/monitor.py": SCAN_MONITOR,
        "src/robot_bringup/package.xml": PACKAGE_XML.format(name="robot_bringup",
                                                            build="ament_python"),
        "src/robot_bringup/setup.py": "from setuptools import setup\nsetup(name='robot_bringup')\n",
        "src/robot_bringup/config/common.yaml": config,
        "src/robot_bringup/launch/lidar.launch.py": launch,
    })


COMMON_YAML = """
    /**:
      ros__parameters:
        rate: 20.0
        frame_id: front_laser
        timeout: 0.5
"""


def findings(root: Path, codes: list[str]) -> list[tuple[str, str, int, str]]:
    from flake8_rosgraph.launch.api import judged_graph
    from flake8_rosgraph.rules import RuleConfig, run_rules

    graph = build_graph(root)
    return sorted((f.code, f.location.path, f.location.line, f.message)
                  for f in run_rules(judged_graph(graph, graph.systems), RuleConfig(), codes))


def test_descriptions_returned_on_different_paths_never_run_together(tmp_path: Path) -> None:
    """``if …: return LaunchDescription([...])`` then another ``return``: one call returns one
    of them, so the driver named ``lidar`` in both is not a duplicate (autoware_tools'
    control_data_collecting_tool: 8 false ROS007, one per node of the two alternatives)."""
    root = lidar_workspace(tmp_path, CHOSEN_LAUNCH, COMMON_YAML)
    assert findings(root, ["ROS007"]) == []
    (system,) = build_graph(root).systems
    assert len(system.nodes) == 5 and all(n.conditional for n in system.nodes)


def test_one_description_still_starts_its_nodes_together(tmp_path: Path) -> None:
    """The twin: two drivers named ``lidar`` in one returned description both start."""
    root = lidar_workspace(tmp_path, ONE_LAUNCH, COMMON_YAML)
    reported = findings(root, ["ROS007"])
    assert [(code, line) for code, _, line, _ in reported] == [("ROS007", 10), ("ROS007", 12)]


def test_a_parameter_file_shared_by_several_nodes_is_judged_against_all_of_them(
        tmp_path: Path) -> None:
    """A ``/**`` file given to the driver and the monitor: each reads its own part
    (``rate`` and ``frame_id`` the driver, ``timeout`` the monitor), so nothing is ignored
    (autoware_tools: 68 ROS204 on such a common file before); a name neither declares is
    reported once, naming both nodes."""
    launch = ONE_LAUNCH.replace(
        "            Node(package='lidar_driver', executable='driver', name='lidar', "
        "parameters=[params]),\n        ])", "        ])")
    assert launch.count("executable='driver'") == 1
    root = lidar_workspace(tmp_path, launch, COMMON_YAML + "        rte: 5.0\n")
    reported = findings(root, ["ROS204"])
    assert len(reported) == 1
    code, path, line, message = reported[0]
    assert (code, path, line) == ("ROS204", "src/robot_bringup/config/common.yaml", 6)
    assert message.startswith("parameter 'rte' is set for nodes '/lidar', '/scan_monitor', "
                              "none of which declares it")


# -- webots_ros2_driver Python plugins named in the robot description ---------------------------
WEBOTS_PLUGIN = """
    import rclpy
    from ackermann_msgs.msg import AckermannDrive
    from sensor_msgs.msg import Range


    class {cls}:
        def init(self, webots_node, properties):
            self.__robot = webots_node.robot
            rclpy.init(args=None)
            self.__node = rclpy.create_node('{node}')
            self.__node.create_subscription(AckermannDrive, 'cmd_ackermann', self.__on_cmd, 1)
            self.__range = self.__node.create_publisher(Range, 'front_range', 1)

        def __on_cmd(self, message):
            self.__robot.setCruisingSpeed(message.speed)

        def step(self):
            rclpy.spin_once(self.__node, timeout_sec=0)
"""


def test_a_webots_plugin_named_in_the_robot_description_is_an_entry_point(tmp_path: Path) -> None:
    """webots_ros2_driver builds the class a ``<webots><plugin type="pkg.module.Class">`` names
    and calls its ``init``: the node it creates there is in the graph (webots_ros2: the Tesla,
    Mavic, Crazyflie and example plugins, 13 sites never analysed before). A C++ plugin, a
    ``<plugin>`` outside ``<webots>`` and a class no description names stay out."""
    root = write(tmp_path, {
        "car/package.xml": PACKAGE_XML.format(name="car", build="ament_python"),
        "car/setup.py": "from setuptools import setup\nsetup(name='car', packages=['car'])\n",
        "car/car/__init__.py": "",
        "car/car/car_driver.py": WEBOTS_PLUGIN.format(cls="CarDriver", node="car_driver"),
        "car/car/spare_driver.py": WEBOTS_PLUGIN.format(cls="SpareDriver", node="spare_driver"),
        "car/car/sim_driver.py": WEBOTS_PLUGIN.format(cls="SimDriver", node="sim_driver"),
        "car/resource/car_webots.urdf": """
            <?xml version="1.0" ?>
            <robot name="Car">
                <webots>
                    <plugin type="car.car_driver.CarDriver" />
                    <plugin type="webots_ros2_control::Ros2Control" />
                </webots>
                <gazebo>
                    <plugin type="car.sim_driver.SimDriver" />
                </gazebo>
            </robot>
        """,
    })
    assert entities(root, ("publishers", "subscriptions")) == {
        "/car_driver": [("publishers", "/front_range"), ("subscriptions", "/cmd_ackermann")]}
    missing = {path.rsplit("/", 1)[-1] for path, _, status in explained(root) if status == "missing"}
    assert missing == {"spare_driver.py", "sim_driver.py"}


# -- the Python half of a hybrid node, built from C++ through pybind11 ---------------------------
def test_a_class_a_cpp_node_builds_through_pybind11_is_an_entry_point(tmp_path: Path) -> None:
    """``py::module::import("guard.guard_module")`` then ``.attr("GuardManager")(...)``: the C++
    node builds the Python class, whose node and entities are in the graph (bitbots_main's
    HCM: 15 sites never analysed before). A class the C++ only reads without calling it adds
    nothing."""
    root = write(tmp_path, {
        "guard/package.xml": PACKAGE_XML.format(name="guard", build="ament_cmake"),
        "guard/CMakeLists.txt": "cmake_minimum_required(VERSION 3.8)\nproject(guard)\n",
        "guard/guard/__init__.py": "",
        "guard/guard/guard_module.py": """
            import rclpy
            from rclpy.node import Node
            from std_msgs.msg import Bool, Float32


            class GuardManager:
                def __init__(self, use_sim_time):
                    rclpy.init(args=None)
                    self.node = Node('guard_py')
                    self.node.create_subscription(Float32, 'battery_voltage', self.on_voltage, 1)

                def on_voltage(self, msg):
                    self.low = msg.data < 11.0

                def tick(self):
                    return self.low


            class SpareManager:
                def __init__(self):
                    self.node = Node('spare_py')
                    self.node.create_publisher(Bool, 'spare', 1)
        """,
        "guard/src/guard.cpp": """
            #include <pybind11/embed.h>
            #include <rclcpp/rclcpp.hpp>
            namespace py = pybind11;

            class GuardCpp : public rclcpp::Node {
             public:
              GuardCpp() : Node("guard_cpp") {
                auto module = py::module::import("guard.guard_module");
                guard_py_ = module.attr("GuardManager")(false);
                spare_class_ = module.attr("SpareManager");
              }
              void tick() { guard_py_.attr("tick")(); }
             private:
              py::object guard_py_;
              py::object spare_class_;
            };
        """,
    })
    got = entities(root, ("publishers", "subscriptions"))
    assert got.get("/guard_py") == [("subscriptions", "/battery_voltage")]
    assert "/spare_py" not in got


def test_a_broken_robot_description_loses_only_its_own_plugins(tmp_path: Path) -> None:
    """A malformed ``*.xacro`` next to the description that names the plugin: the plugin is
    still an entry point, and nothing crashes."""
    root = write(tmp_path, {
        "car/package.xml": PACKAGE_XML.format(name="car", build="ament_python"),
        "car/setup.py": "from setuptools import setup\nsetup(name='car', packages=['car'])\n",
        "car/car/__init__.py": "",
        "car/car/car_driver.py": WEBOTS_PLUGIN.format(cls="CarDriver", node="car_driver"),
        "car/resource/broken.urdf.xacro": "<robot><webots><plugin type='car.x.Y'></robot>",
        "car/resource/car_webots.urdf": """
            <robot name="Car"><webots><plugin type="car.car_driver.CarDriver" /></webots></robot>
        """,
    })
    assert list(entities(root, ("publishers",))) == ["/car_driver"]


# -- a folder without __init__.py inside a package ---------------------------------------------
OPERATOR_GUI = {
    "operator_gui/package.xml": PACKAGE_XML.format(name="operator_gui", build="ament_cmake"),
    "operator_gui/gui/server.py": """
        import rclpy
        from rclpy.node import Node

        from backend.handlers.drive import DriveHandler
        from backend.handlers.arm import ArmHandler


        def main():
            rclpy.init()
            node = Node('operator_gui')
            for handler in (DriveHandler(node), ArmHandler(node)):
                handler.setup()
            rclpy.spin(node)
    """,
    "operator_gui/gui/backend/__init__.py": "",
    # No __init__.py in handlers/: a namespace package inside the regular package backend.
    "operator_gui/gui/backend/handlers/base.py": """
        from std_msgs.msg import String


        class Handler:
            def __init__(self, node, endpoint):
                self.node = node
                self.status = node.create_publisher(String, f'/gui/{endpoint}/status', 1)
    """,
    "operator_gui/gui/backend/handlers/drive.py": """
        from geometry_msgs.msg import Twist

        from backend.handlers.base import Handler


        class DriveHandler(Handler):
            def __init__(self, node):
                super().__init__(node, 'drive')

            def setup(self):
                self.cmd = self.node.create_publisher(Twist, '/joystick_vel_cmd', 1)
    """,
    "operator_gui/gui/backend/handlers/arm.py": """
        from backend.handlers.base import Handler
        from backend.handlers.gripper import GripperCommand


        class ArmHandler(Handler):
            def __init__(self, node):
                super().__init__(node, 'arm')

            def setup(self):
                self.cmd = self.node.create_publisher(GripperCommand, '/gripper_cmd', 1)
    """,
    # Another top-level module named like the namespace folder's module: never taken for it.
    "operator_gui/tools/base.py": """
        class Handler:
            def __init__(self, node, endpoint):
                self.node = node
    """,
}


def test_a_folder_without_init_inside_a_package_is_a_namespace_package(tmp_path: Path) -> None:
    """``backend.handlers.base`` is ``backend/handlers/base.py`` when ``backend`` is a package and
    ``handlers/`` has no ``__init__.py`` (mrover's basestation GUI: 10 creation sites in its
    websocket handlers were missing, their imports "not resolved")."""
    root = write(tmp_path, OPERATOR_GUI)
    assert entities(root, ("publishers",)) == {"/operator_gui": [
        ("publishers", "/gripper_cmd"), ("publishers", "/gui/arm/status"),
        ("publishers", "/gui/drive/status"), ("publishers", "/joystick_vel_cmd")]}


def test_a_module_missing_from_the_namespace_folder_stays_unresolved(tmp_path: Path) -> None:
    """``backend.handlers.gripper`` names no file: the import is reported as not resolved, and
    nothing else (``tools/base.py``) is taken for it."""
    root = write(tmp_path, OPERATOR_GUI)
    graph, analysis = analyse(root)
    [gripper] = [e for e in explain(analysis, graph).explanations
                 if e.site.path.endswith("handlers/arm.py")]
    assert gripper.status == "unknown"
    assert "imports not resolved in the workspace: backend.handlers.gripper" in gripper.reasons
