"""Code that a framework runs, not the workspace: found on repositories outside every test set
(bdaiinstitute/spot_ros2, ros-visualization/rqt_bag, SSL-Roots/consai_ros2, kas-lab/suave), on realistic multi-file packages. Each mechanism follows what the
framework does at run time, with a twin where following it must not invent an entity."""
from __future__ import annotations

from pathlib import Path

from flake8_rosgraph.analysis import analyse, build_graph
from flake8_rosgraph.explain import explain

from test_workspace_discovery import PACKAGE_XML, write


def entities(root: Path) -> dict[str | None, list[tuple[str, str]]]:
    """Each node's publishers, subscriptions, services and clients as ``(kind, name or "?")``."""
    kinds = ("publishers", "subscriptions", "services", "clients")
    return {node.fqn: sorted((e.kind, e.name or "?") for e in node.entities if e.kind in kinds)
            for node in build_graph(root).nodes}


def explained(root: Path) -> dict[tuple[str, int], tuple[str, tuple[str, ...]]]:
    graph, analysis = analyse(root)
    return {(e.site.path, e.site.line): (e.status, e.reasons)
            for e in explain(analysis, graph).explanations}


# -- synchros2: Node subclasses that its process scope builds ---------------------------------
ROBOT_DRIVER = {
    "quad_driver/package.xml": PACKAGE_XML.format(name="quad_driver", build="ament_cmake"),
    "quad_driver/CMakeLists.txt": """
        cmake_minimum_required(VERSION 3.8)
        project(quad_driver)
        find_package(ament_cmake_python REQUIRED)
        ament_python_install_package(quad_driver)
        install(PROGRAMS quad_driver/driver_node.py DESTINATION lib/${PROJECT_NAME} RENAME quad_driver)
        ament_package()
    """,
    "quad_driver/quad_driver/__init__.py": "",
    "quad_driver/quad_driver/services.py": """
        from std_srvs.srv import Trigger


        def add_power_services(node, on_power):
            for action in ('power_on', 'power_off'):
                node.create_service(Trigger, action, on_power)
    """,
    "quad_driver/quad_driver/driver_node.py": """
        import synchros2.process as ros_process
        from geometry_msgs.msg import Twist
        from rclpy.callback_groups import MutuallyExclusiveCallbackGroup
        from sensor_msgs.msg import JointState
        from synchros2.node import Node

        from quad_driver.services import add_power_services


        class QuadDriver(Node):
            def __init__(self, **kwargs):
                super().__init__('quad_driver', **kwargs)
                group = MutuallyExclusiveCallbackGroup()
                self.joint_pub = self.create_publisher(JointState, 'joint_states', 10)
                self.create_subscription(Twist, 'cmd_vel', self.on_cmd, 1, callback_group=group)
                add_power_services(self, self.on_power)

            def on_cmd(self, msg):
                pass

            def on_power(self, request, response):
                return response


        class Watchdog(Node):
            def __init__(self):
                super().__init__('quad_watchdog', default_callback_group=MutuallyExclusiveCallbackGroup())
                self.create_subscription(JointState, 'joint_states', self.on_joints, 10)

            def on_joints(self, msg):
                pass


        @ros_process.main(prebaked=False)
        def main():
            ros_process.spin(QuadDriver)


        if __name__ == '__main__':
            main()
    """,
    # The process scope's own node is named after the executable: not followed.
    "quad_driver/quad_driver/teleop.py": """
        import synchros2.process as ros_process
        from geometry_msgs.msg import Twist


        @ros_process.main()
        def main():
            pub = main.node.create_publisher(Twist, 'cmd_vel', 1)
            pub.publish(Twist())
    """,
}


def test_synchros2_node_subclasses_are_node_classes(tmp_path: Path) -> None:
    """A ``synchros2.node.Node`` subclass is a node class: its name and entities are known,
    through a helper in another module and with synchros2's own ``default_callback_group``
    argument; built by ``process.spin`` (or nobody), it is an entry point (spot_ros2: 12 -> 83
    of 154 creation sites fully known)."""
    root = write(tmp_path, ROBOT_DRIVER)
    assert entities(root) == {
        "/quad_driver": [("publishers", "/joint_states"), ("services", "/power_off"),
                         ("services", "/power_on"), ("subscriptions", "/cmd_vel")],
        "/quad_watchdog": [("subscriptions", "/joint_states")],
    }


def test_the_synchros2_process_node_is_not_invented(tmp_path: Path) -> None:
    """``main.node`` of a ``@process.main()`` program is named after the executable that runs
    it: no node is made up for it, and ``--explain`` says the receiver is not modelled."""
    root = write(tmp_path, ROBOT_DRIVER)
    status, reasons = explained(root)[("quad_driver/quad_driver/teleop.py", 7)]
    assert status == "missing"
    assert "`main.node` is not known to be a modelled library object here" in reasons


# -- rqt: plugin.xml says which provider builds a plugin --------------------------------------
def rqt_package(base_class_type: str) -> dict[str, str]:
    """An rqt plugin on qt_gui's own ``Plugin`` class (as rqt_bag and consai_visualizer are),
    exported with ``base_class_type`` (none when empty); its widget, in another module, creates
    its entities on the node of the context."""
    written = f' base_class_type="{base_class_type}"' if base_class_type else ""
    return {
        "rqt_mission/package.xml": PACKAGE_XML.format(name="rqt_mission", build="ament_python").replace(
            "</export>", '<rqt_gui plugin="${prefix}/plugin.xml"/></export>'),
        "rqt_mission/plugin.xml": f"""
            <library path="src">
              <class name="Mission" type="rqt_mission.mission.Mission"{written}>
                <description>Mission control</description>
              </class>
            </library>
        """,
        "rqt_mission/setup.py": """
            from setuptools import setup
            setup(name='rqt_mission', packages=['rqt_mission'], package_dir={'': 'src'})
        """,
        "rqt_mission/src/rqt_mission/__init__.py": "",
        "rqt_mission/src/rqt_mission/mission.py": """
            from qt_gui.plugin import Plugin

            from .mission_widget import MissionWidget


            class Mission(Plugin):
                def __init__(self, context):
                    super(Mission, self).__init__(context)
                    self._widget = MissionWidget(context.node)
                    context.add_widget(self._widget)
        """,
        "rqt_mission/src/rqt_mission/mission_widget.py": """
            from python_qt_binding.QtWidgets import QWidget
            import rclpy.qos
            from std_msgs.msg import String
            from std_srvs.srv import Trigger


            class MissionWidget(QWidget):
                def __init__(self, node):
                    super().__init__()
                    self._node = node
                    self._status = node.create_subscription(
                        String, 'mission/status', self.on_status, rclpy.qos.qos_profile_sensor_data)
                    self._abort = node.create_client(Trigger, 'mission/abort')

                def on_status(self, msg):
                    self.update()
        """,
    }


def test_an_rqt_plugin_on_qt_guis_base_gets_the_ros_context(tmp_path: Path) -> None:
    """A plugin exported as an ``rqt_gui_py::Plugin`` is built by rqt_gui_py's provider, with
    the ROS 2 context, whatever its Python base: its entities are on the rqt node (rqt_bag,
    consai_visualizer: 6 creation sites missing before)."""
    root = write(tmp_path, rqt_package("rqt_gui_py::Plugin"))
    assert entities(root) == {
        None: [("clients", "/mission/abort"), ("subscriptions", "/mission/status")]}
    [node] = build_graph(root).nodes
    assert (node.namespace, node.location.path) == ("/", "rqt_mission/src/rqt_mission/mission.py")


def test_a_plugin_export_without_its_provider_gets_no_invented_node(tmp_path: Path) -> None:
    """Exported without a base class type, the plugin's provider is not known: no rqt node is
    made up for it, and ``--explain`` says the widget's node is unknown."""
    root = write(tmp_path, rqt_package(""))
    assert entities(root) == {}
    status, reasons = explained(root)[("rqt_mission/src/rqt_mission/mission_widget.py", 11)]
    assert status == "missing"
    assert "`node` is not known to be a modelled library object here" in reasons


# -- pytest: fixtures are what the test functions' parameters receive -----------------------
GRIPPER = {
    "gripper/package.xml": PACKAGE_XML.format(name="gripper", build="ament_python"),
    "gripper/setup.py": """
        from setuptools import setup
        setup(name='gripper', packages=['gripper'],
              entry_points={'console_scripts': ['gripper = gripper.gripper_node:main']})
    """,
    "gripper/gripper/__init__.py": "",
    "gripper/gripper/gripper_node.py": """
        import rclpy
        from rclpy.action import ActionServer
        from rclpy.node import Node
        from control_msgs.action import GripperCommand


        class GripperNode(Node):
            def __init__(self, name='gripper'):
                super().__init__(name)
                self.server = ActionServer(self, GripperCommand, 'gripper_cmd', self.execute)

            def execute(self, goal_handle):
                return GripperCommand.Result()


        def main():
            rclpy.init()
            rclpy.spin(GripperNode())
    """,
    # Shared by every test of the folder: a helper node, and the node under test.
    "gripper/test/conftest.py": """
        import pytest
        import rclpy
        from rclpy.node import Node

        from gripper.gripper_node import GripperNode


        @pytest.fixture
        def helper():
            node = Node('gripper_test_helper')
            try:
                yield node
            finally:
                node.destroy_node()


        @pytest.fixture(name='gripper')
        def gripper_under_test(helper):
            return GripperNode('gripper_under_test')
    """,
    "gripper/test/test_gripper.py": """
        import pytest
        from rclpy.action import ActionClient
        from control_msgs.action import GripperCommand
        from std_msgs.msg import Float64
        from std_srvs.srv import Trigger


        @pytest.fixture
        def status_probe(helper):
            yield helper.create_publisher(Float64, 'gripper/position', 1)


        def test_goal_is_accepted(helper, gripper, status_probe):
            client = ActionClient(helper, GripperCommand, 'gripper_cmd')
            assert client.wait_for_server(timeout_sec=1.0)


        @pytest.mark.parametrize('helper', ['a', 'b'])
        def test_parametrized_name_is_no_fixture(helper):
            helper.create_client(Trigger, 'calibrate')
    """,
    # Another folder's conftest is not seen from gripper/test.
    "tools/test/conftest.py": """
        import pytest
        from rclpy.node import Node


        @pytest.fixture
        def bench():
            return Node('bench')
    """,
    "gripper/test/test_bench.py": """
        import rclpy
        from std_srvs.srv import Trigger


        def test_bench_is_not_a_fixture_here(bench):
            bench.create_service(Trigger, 'reset', lambda req, res: res)
    """,
}


def test_pytest_passes_each_test_the_fixture_of_its_parameters_name(tmp_path: Path) -> None:
    """A test function's parameter is the fixture of that name from its module or a
    ``conftest.py`` above it: what a generator fixture yields or a fixture returns, fixtures
    using fixtures, ``name=`` renames (kas-lab/suave: 15 creation sites of its tests were on
    an unknown ``test_node``)."""
    root = write(tmp_path, GRIPPER)
    graph = build_graph(root)
    ends = {(n.fqn, e.kind, e.name) for n in graph.nodes for e in n.entities
            if e.kind in ("publishers", "action_clients", "action_servers", "services", "clients")}
    assert ends == {
        ("/gripper", "action_servers", "/gripper_cmd"),
        ("/gripper_under_test", "action_servers", "/gripper_cmd"),
        ("/gripper_test_helper", "action_clients", "/gripper_cmd"),
        ("/gripper_test_helper", "publishers", "/gripper/position"),
    }


def test_a_parametrized_or_unseen_name_is_not_a_fixture(tmp_path: Path) -> None:
    """A parameter ``parametrize`` fills, or named like a fixture of a ``conftest.py`` the
    test cannot see, gets no fixture: nothing is created on it, and ``--explain`` says so."""
    root = write(tmp_path, GRIPPER)
    found = explained(root)
    for site in (("gripper/test/test_gripper.py", 20), ("gripper/test/test_bench.py", 6)):
        status, reasons = found[site]
        assert status == "missing"
        assert any(r.startswith("`helper` is not known") or r.startswith("`bench` is not known")
                   for r in reasons)


def test_a_test_waits_for_its_fixture_and_says_so(tmp_path: Path) -> None:
    """A fixture that never produces a value (it always raises) never lets its test run, as
    pytest errors the test: nothing is created on it, and ``--explain`` names the fixture."""
    root = write(tmp_path, dict(GRIPPER, **{"gripper/test/test_hardware.py": """
        import pytest
        import rclpy
        from sensor_msgs.msg import Image


        @pytest.fixture
        def camera_node():
            raise RuntimeError('set CAMERA_DEVICE to run the hardware tests')


        def test_camera_streams(camera_node):
            camera_node.create_subscription(Image, 'image_raw', print, 1)
    """}))
    status, reasons = explained(root)[("gripper/test/test_hardware.py", 12)]
    assert (status, reasons) == ("missing", (
        "pytest runs test_camera_streams with fixture `camera_node`, which the analysis never "
        "sees return or yield a value",))
