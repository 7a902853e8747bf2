"""Findings and misses of the rules on a ninth round of public repositories (a grasping GUI,
a debugging course's relay system, rover stacks), each fixed by a general mechanism: a
realistic multi-file workspace holding the pattern, and its near-identical twin, one of which
must be reported and the other stay quiet."""
from __future__ import annotations

from pathlib import Path

from test_precision_on_survey6_repos import ament_python, sites
from test_recall_mechanisms import findings
from test_workspace_discovery import write

# -- a node class keeping its own `namespace` attribute ---------------------------------------------
GRASP_SERVER = """
    import rclpy
    from rclpy.node import Node
    from std_srvs.srv import Trigger


    class GraspServer(Node):
        def __init__(self):
            super().__init__('visual_grasp')
            self.create_service(Trigger, '/visual_grasp/set_target', self.on_target)
            self.create_service(Trigger, '/visual_grasp/calibrate', self.on_target)

        def on_target(self, request, response):
            response.success = True
            return response


    def main():
        rclpy.init()
        rclpy.spin(GraspServer())
"""

GRASP_GUI = """
    import rclpy
    from rclpy.node import Node
    from std_srvs.srv import Trigger


    class CalibrationClient:
        \"\"\"Calls the grasp server's calibration service under the prefix it is given.\"\"\"

        def __init__(self, node: Node, prefix: str) -> None:
            root = '/' + prefix.strip('/')
            self._client = node.create_client(Trigger, root + '/calibrate')


    class GraspGui(Node):
        def __init__(self):
            super().__init__('visual_grasp_gui')
            self.namespace = {namespace}
            self.node_name = 'grasp_panel'
            self._create_clients()

        def _create_clients(self):
            root = self.namespace.rstrip('/')
            self.set_target = self.create_client(Trigger, root + '/set_target')
            self.calibration = CalibrationClient(self, root)


    def main():
        rclpy.init()
        rclpy.spin(GraspGui())
"""


def grasp_workspace(root: Path, namespace: str) -> Path:
    return write(root, {
        **ament_python("grasp_server", "'server = grasp_server.server:main'"),
        "grasp_server/grasp_server/server.py": GRASP_SERVER,
        **ament_python("grasp_gui", "'gui = grasp_gui.gui:main'"),
        "grasp_gui/grasp_gui/gui.py": GRASP_GUI.format(namespace=namespace),
    })


def test_a_node_class_attribute_called_namespace_is_the_class_own(tmp_path: Path) -> None:
    """Project_LINK's grasp GUI stores ``self.namespace = '/visual_grasp'`` on its Node subclass
    and builds its clients from it in a helper method. rclpy keeps the node's namespace in rcl
    (``get_namespace()``), not in an attribute, so the class's own value is the only one:
    no '//calibrate' (a false ROS006) and no '/set_target' beside '/visual_grasp/set_target'."""
    root = grasp_workspace(tmp_path, "'/visual_grasp'")
    assert findings(root, ["ROS006", "ROS008"]) == []


def test_a_misspelt_namespace_attribute_is_reported(tmp_path: Path) -> None:
    root = grasp_workspace(tmp_path, "'/visual_grap'")
    reported = findings(root, ["ROS006", "ROS008"])
    assert sites(reported) == [("ROS008", "grasp_gui/grasp_gui/gui.py", 11),
                               ("ROS008", "grasp_gui/grasp_gui/gui.py", 23)]


# -- a unit test hosting the node under test under its product name ---------------------------------
RELAY = """
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import Int32


    class DelayedRelay:
        \"\"\"Republishes every number it hears one tick later.\"\"\"

        def __init__(self, node: Node) -> None:
            self._node = node
            self._pub = node.create_publisher(Int32, 'delayed_number', 10)
            node.create_subscription(Int32, 'number', self._pub.publish, 10)


    def main():
        rclpy.init()
        node = rclpy.create_node('delayed_relay')
        DelayedRelay(node)
        rclpy.spin(node)
"""

INCREMENTER = """
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import Int32


    class Incrementer(Node):
        def __init__(self):
            super().__init__('incrementer')
            self.create_subscription(Int32, 'number', self.on_number, 10)
            self._pub = self.create_publisher(Int32, 'incremented_number', 10)

        def on_number(self, msg):
            self._pub.publish(Int32(data=msg.data + 1))


    def main():
        rclpy.init()
        rclpy.spin(Incrementer())
"""

SYSTEM_LAUNCH = """
    from launch import LaunchDescription
    from launch_ros.actions import Node


    def generate_launch_description():
        return LaunchDescription([
            Node(package='relay_demo', executable='incrementer', name='incrementer'),
            Node(package='relay_demo', executable='delayed_relay', name='delayed_relay',
                 remappings=[('number', 'incremented_number'), ('delayed_number', 'number')]),
        ])
"""

RELAY_TEST = """
    import rclpy
    from std_msgs.msg import Int32

    import relay_demo.delayed_relay


    def test_relay_delays_each_number():
        rclpy.init()
        node = rclpy.create_node('delayed_relay')
        relay_demo.delayed_relay.DelayedRelay(node)
        probe = rclpy.create_node({probe})
        feeder = probe.create_publisher(Int32, 'number', 10)
        heard = []
        probe.create_subscription(Int32, 'delayed_number', heard.append, 10)
        feeder.publish(Int32(data=1))
        rclpy.shutdown()
"""


def relay_workspace(root: Path, probe: str) -> Path:
    return write(root, {
        **ament_python("relay_demo", "'delayed_relay = relay_demo.delayed_relay:main', "
                                     "'incrementer = relay_demo.incrementer:main'"),
        "relay_demo/relay_demo/delayed_relay.py": RELAY,
        "relay_demo/relay_demo/incrementer.py": INCREMENTER,
        "relay_demo/launch/system.launch.py": SYSTEM_LAUNCH,
        "relay_demo/test/test_delayed_relay.py": RELAY_TEST.format(probe=probe),
    })


def test_a_unit_test_hosting_the_node_under_test_does_not_run_beside_the_product(tmp_path: Path) -> None:
    """dyno_ros2_courses: a test module creates ``delayed_relay`` to host the class under test
    and feeds it '/number'; the launched product of that name talks over '/number' too. The
    test stands in for the product (pytest runs it alone), so the two never run together."""
    assert findings(relay_workspace(tmp_path, "'relay_probe'"), ["ROS007"]) == []


def test_two_nodes_of_one_name_in_one_unit_test_are_reported(tmp_path: Path) -> None:
    """The probe copied the name of the node it probes: within the test both run, and talk."""
    reported = findings(relay_workspace(tmp_path, "'delayed_relay'"), ["ROS007"])
    assert sites(reported) == [("ROS007", "relay_demo/test/test_delayed_relay.py", 9),
                               ("ROS007", "relay_demo/test/test_delayed_relay.py", 11)]



MONITOR = """
    from rclpy.node import Node
    from std_msgs.msg import Int32


    class RelayMonitor(Node):
        def __init__(self):
            super().__init__('relay_monitor')
            self.create_subscription(Int32, 'delayed_number', self.on_number, 10)

        def on_number(self, msg):
            self.get_logger().info(str(msg.data))
"""

MONITOR_TEST = """
    import rclpy
    from std_msgs.msg import Int32

    from relay_demo.monitor import RelayMonitor


    def test_monitor_logs_each_number():
        rclpy.init()
        monitor = RelayMonitor()
        probe = rclpy.create_node({probe})
        probe.create_publisher(Int32, 'delayed_number', 10).publish(Int32(data=1))
        rclpy.spin_once(monitor, timeout_sec=1.0)
        rclpy.shutdown()
"""


def monitor_workspace(root: Path, probe: str) -> Path:
    relay_workspace(root, "'relay_probe'")
    return write(root, {"relay_demo/relay_demo/monitor.py": MONITOR,
                        "relay_demo/test/test_monitor.py": MONITOR_TEST.format(probe=probe)})


def test_a_unit_test_probe_named_like_the_product_node_it_runs_is_reported(tmp_path: Path) -> None:
    """The test runs the product's node class itself: its probe, named alike, runs beside it."""
    reported = findings(monitor_workspace(tmp_path, "'relay_monitor'"), ["ROS007"])
    assert sites(reported) == [("ROS007", "relay_demo/relay_demo/monitor.py", 7),
                               ("ROS007", "relay_demo/test/test_monitor.py", 10)]


def test_a_unit_test_probe_of_its_own_name_is_quiet(tmp_path: Path) -> None:
    assert findings(monitor_workspace(tmp_path, "'monitor_probe'"), ["ROS007"]) == []

# -- a test script beside the workspace calling the product's service ------------------------------
MODBUS_MANAGER = """
    import rclpy
    from rclpy.node import Node
    from std_srvs.srv import Trigger


    class ModbusManager(Node):
        def __init__(self):
            super().__init__('modbus_manager')
            self.create_service(Trigger, '/modbus_request', self.on_request)

        def on_request(self, request, response):
            response.success = True
            return response


    def main():
        rclpy.init()
        rclpy.spin(ModbusManager())
"""

MOTOR_DEVICE = """
    import rclpy
    from rclpy.node import Node
    from std_srvs.srv import Trigger


    class MotorDevice(Node):
        def __init__(self):
            super().__init__('motor_device')
            self.modbus = self.create_client(Trigger, '/modbus_request')


    def main():
        rclpy.init()
        rclpy.spin(MotorDevice())
"""

FLASH_SCRIPT = """
    import rclpy
    from rclpy.node import Node
    from std_srvs.srv import Trigger


    class FlashControlTest(Node):
        def __init__(self):
            super().__init__('flash_control_test')
            self.client = self.create_client(Trigger, {service})
            while not self.client.wait_for_service(timeout_sec=1.0):
                self.get_logger().info('waiting for the modbus service')


    if __name__ == '__main__':
        rclpy.init()
        node = FlashControlTest()
        node.client.call_async(Trigger.Request())
        rclpy.spin(node)
"""


def modbus_workspace(root: Path, service: str) -> Path:
    return write(root, {
        **{f"colcon_ws/src/{rel}": text for rel, text in ament_python(
            "modbus_driver", "'manager = modbus_driver.manager:main', 'motor = modbus_driver.motor:main'").items()},
        "colcon_ws/src/modbus_driver/modbus_driver/manager.py": MODBUS_MANAGER,
        "colcon_ws/src/modbus_driver/modbus_driver/motor.py": MOTOR_DEVICE,
        "scripts/test_flash_control.py": FLASH_SCRIPT.format(service=service),
    })


def test_a_test_script_misspelling_a_product_service_is_reported(tmp_path: Path) -> None:
    """robot_dc: ``scripts/test_flash_control.py`` (a test module by its name, so a fixture of
    its own folder) calls the Modbus manager's service. The product is outside the fixture's
    scope, so it never serves the script; but it still spells the name the script means."""
    reported = findings(modbus_workspace(tmp_path, "'/mdobus_request'"), ["ROS008"])
    assert sites(reported) == [("ROS008", "scripts/test_flash_control.py", 9)]
    assert "did you mean '/modbus_request'" in reported[0][3]


def test_a_test_script_calling_the_product_service_by_its_name_is_quiet(tmp_path: Path) -> None:
    assert findings(modbus_workspace(tmp_path, "'/modbus_request'"), ["ROS008"]) == []
