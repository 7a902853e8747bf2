"""Seeded wiring bugs the rules missed on further public repositories (an ASR gateway, robot
bring-ups), each fixed by a general mechanism: a realistic multi-file workspace holding the
bug, and its near-identical correct twin, which must stay quiet."""
from __future__ import annotations

from pathlib import Path

from test_precision_on_survey6_repos import ament_python, sites
from test_recall_mechanisms import findings
from test_workspace_discovery import write

# -- a bridge whose helpers create every client its callers name ------------------------------------
RUNTIME = """
    import rclpy
    from rclpy.action import ActionServer
    from rclpy.node import Node
    from std_srvs.srv import Trigger

    from example_interfaces.action import Fibonacci


    class Runtime(Node):
        def __init__(self):
            super().__init__('asr_runtime')
            self.create_service(Trigger, '/asr/start_session', self.on_start)
            self.create_service(Trigger, '/asr/stop_session', self.on_stop)
            ActionServer(self, Fibonacci, '/asr/transcribe', self.on_transcribe)
            ActionServer(self, Fibonacci, '/asr/benchmark', self.on_transcribe)

        def on_start(self, request, response):
            response.success = True
            return response

        def on_stop(self, request, response):
            response.success = True
            return response

        def on_transcribe(self, goal):
            goal.succeed()
            return Fibonacci.Result()


    def main():
        rclpy.init()
        rclpy.spin(Runtime())
"""

BRIDGE = """
    import threading

    import rclpy
    from rclpy.action import ActionClient
    from rclpy.node import Node
    from std_srvs.srv import Trigger

    from example_interfaces.action import Fibonacci


    class Bridge:
        def __init__(self):
            self._lock = threading.Lock()
            self._node = Node('asr_gateway_bridge')
            self._clients = {{}}
            self._action_clients = {{}}

        def _client(self, service_type, service_name):
            with self._lock:
                client = self._clients.get(service_name)
                if client is None:
                    client = self._node.create_client(service_type, service_name)
                    self._clients[service_name] = client
                return client

        def _action_client(self, action_type, action_name):
            with self._lock:
                client = self._action_clients.get(action_name)
                if client is None:
                    client = ActionClient(self._node, action_type, action_name)
                    self._action_clients[action_name] = client
                return client

        def start(self):
            return self._client(Trigger, {start}).call_async(Trigger.Request())

        def stop(self):
            return self._client(Trigger, '/asr/stop_session').call_async(Trigger.Request())

        def transcribe(self, goal):
            return self._action_client(Fibonacci, {transcribe}).send_goal_async(goal)

        def benchmark(self, goal):
            return self._action_client(Fibonacci, '/asr/benchmark').send_goal_async(goal)


    def main():
        rclpy.init()
        bridge = Bridge()
        bridge.start()
        rclpy.spin(bridge._node)
"""


def bridge_workspace(root: Path, start: str = "'/asr/start_session'",
                     transcribe: str = "'/asr/transcribe'") -> Path:
    return write(root, {
        **ament_python("asr_runtime", "'runtime = asr_runtime.runtime:main'"),
        "asr_runtime/asr_runtime/runtime.py": RUNTIME,
        **ament_python("asr_gateway", "'bridge = asr_gateway.bridge:main'"),
        "asr_gateway/asr_gateway/bridge.py": BRIDGE.format(start=start, transcribe=transcribe),
    })


def test_a_misspelt_name_passed_to_a_client_helper_is_reported(tmp_path: Path) -> None:
    """ros2_ASR's gateway creates each client in ``_service_client(type, name)``; the calls that
    name ``/asr/start_session`` and ``/asr/stop_session`` are two clients, not two
    configurations of one, so the misspelt one dangles however well the other is served."""
    root = bridge_workspace(tmp_path, start="'/asr/strat_session'")
    reported = findings(root, ["ROS008"])
    assert sites(reported) == [("ROS008", "asr_gateway/asr_gateway/bridge.py", 22)]
    assert "'/asr/strat_session' has no server; did you mean '/asr/start_session'" in reported[0][3]


def test_a_misspelt_name_passed_to_an_action_client_helper_is_reported(tmp_path: Path) -> None:
    root = bridge_workspace(tmp_path, transcribe="'/asr/transcibe'")
    assert sites(findings(root, ["ROS009"])) == [("ROS009", "asr_gateway/asr_gateway/bridge.py", 30)]


def test_helpers_whose_every_name_is_served_are_quiet(tmp_path: Path) -> None:
    assert findings(bridge_workspace(tmp_path), ["ROS008", "ROS009"]) == []


def test_one_call_choosing_between_names_is_still_one_client(tmp_path: Path) -> None:
    """One call of the helper with ``a if … else b`` is one client in two configurations: the
    served alternative makes it work, the other is not reported."""
    root = bridge_workspace(tmp_path, start="'/asr/start_session' if self._lock else '/asr/begin'")
    assert findings(root, ["ROS008"]) == []


# -- a test's publisher whose QoS the product's subscription refuses --------------------------------
MANAGER = """
    import rclpy
    from geographic_msgs.msg import GeoPath
    from rclpy.node import Node


    class NavManager(Node):
        def __init__(self):
            super().__init__('nav_manager')
            self.declare_parameter('waypoints_topic', '/gps_waypoints')
            topic = self.get_parameter('waypoints_topic').value
            self.create_subscription(GeoPath, topic, self.on_waypoints, 10)

        def on_waypoints(self, msg):
            self.get_logger().info(f'{len(msg.poses)} waypoints')


    def main():
        rclpy.init()
        rclpy.spin(NavManager())
"""

NAV_TEST = """
    import rclpy
    from geographic_msgs.msg import GeoPath
    from rclpy.qos import qos_profile_sensor_data


    def test_manager_follows_waypoints():
        rclpy.init()
        node = rclpy.create_node('waypoint_feeder')
        publisher = node.create_publisher(GeoPath, '/gps_waypoints', {qos})
        publisher.publish(GeoPath())
        node.destroy_node()
        rclpy.shutdown()
"""


def nav_workspace(root: Path, qos: str) -> Path:
    return write(root, {
        **ament_python("nav_manager", "'manager = nav_manager.manager:main'"),
        "nav_manager/nav_manager/manager.py": MANAGER,
        "nav_manager/test/test_waypoints.py": NAV_TEST.format(qos=qos),
    })


def test_a_test_publisher_the_product_refuses_is_reported_at_the_test(tmp_path: Path) -> None:
    """rcdt_robotics: a test feeds the product's reliable subscription through a best-effort
    publisher; the product does not see test fixtures, so the pair was never compared."""
    reported = findings(nav_workspace(tmp_path, "qos_profile_sensor_data"), ["ROS005"])
    assert sites(reported) == [("ROS005", "nav_manager/test/test_waypoints.py", 9)]
    assert "best-effort publisher, reliable subscription" in reported[0][3]


def test_a_test_publisher_of_matching_qos_is_quiet(tmp_path: Path) -> None:
    assert findings(nav_workspace(tmp_path, "10"), ["ROS005"]) == []


def test_a_helper_forwarding_names_nobody_near_publishes_is_an_interface(tmp_path: Path) -> None:
    """mrover's GUI bridge subscribes, through one helper, to every topic it forwards, many of
    them published by firmware bridges the analysis does not see: a helper's unserved name is
    reported only as a slip of a name the workspace uses, never as the odd one out."""
    root = bridge_workspace(tmp_path, start="'/arm/calibrate'")
    assert findings(root, ["ROS008"]) == []
