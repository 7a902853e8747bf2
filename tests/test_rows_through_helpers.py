"""A table of names and types whose rows reach the creation call through the workspace's own helper.

Found on a ninth round of real repositories: a robot driver's example client keeps a
``{service name: service type}`` table and connects each row through a helper
(``{name: wait_for_service(self.node, name, srv_type) for name, srv_type in
self.services.items()}``). Rows of a written-out table were split only at a library creation
call, so the helper ran once with every name and every type joined, and the graph left each
client's type unknown (which goes with which was lost). A call of a workspace function given
several columns of a short table is now evaluated once per row (one calling context each), so
each client has its own type. Twins: a table longer than the contexts a function keeps stays
joined (types unknown, none invented), and a helper given one column is called once, as before.
"""
from __future__ import annotations

from pathlib import Path

from test_recall_globals_and_escapes import package
from test_workspace_discovery import write

from flake8_rosgraph.analysis import build_graph

CONNECT = """
    from rclpy.action import ActionClient


    def wait_for_service(node, srv_name, srv_type, timeout=10.0):
        client = node.create_client(srv_type, srv_name)
        if not client.wait_for_service(timeout_sec=timeout):
            raise RuntimeError(f'{srv_name} not available')
        return client


    def wait_for_action(node, action_name, action_type, timeout=10.0):
        client = ActionClient(node, action_type, action_name)
        if not client.wait_for_server(timeout_sec=timeout):
            raise RuntimeError(f'{action_name} not available')
        return client
"""

ROBOT = """
    import rclpy
    from control_msgs.action import FollowJointTrajectory
    from controller_manager_msgs.srv import SwitchController
    from rclpy.node import Node
    from std_srvs.srv import Trigger
    from ur_msgs.srv import SetIO

    from arm_examples.connect import wait_for_action, wait_for_service

    {table}


    class Robot:
        def __init__(self, node):
            self.node = node
            self.service_interfaces = SERVICES
            self.connect()

        def connect(self):
            self.service_clients = {{
                srv_name: wait_for_service(self.node, srv_name, srv_type)
                for (srv_name, srv_type) in self.service_interfaces.items()
            }}
            for action_name in ('/scaled_jtc/follow_joint_trajectory', '/jtc/follow_joint_trajectory'):
                wait_for_action(self.node, action_name, FollowJointTrajectory)


    def main():
        rclpy.init()
        node = Node('robot_driver_example')
        Robot(node)
        rclpy.spin(node)
"""

SHORT = """SERVICES = {
        '/io_and_status_controller/set_io': SetIO,
        '/dashboard_client/play': Trigger,
        '/controller_manager/switch_controller': SwitchController,
    }"""


def _clients(root: Path) -> dict[str, list[tuple[str, str | None]]]:
    return {kind: sorted((e.name, e.type) for node in build_graph(root).nodes for e in node.entities
                         if e.kind == kind)
            for kind in ("clients", "action_clients")}


def _workspace(tmp_path: Path, table: str) -> Path:
    return write(tmp_path, package("arm_examples", "'robot = arm_examples.robot:main'", {
        "connect": CONNECT, "robot": ROBOT.format(table=table)}))


def test_each_row_reaches_the_helper_with_its_own_type(tmp_path: Path) -> None:
    found = _clients(_workspace(tmp_path, SHORT))
    assert found["clients"] == [
        ("/controller_manager/switch_controller", "controller_manager_msgs/srv/SwitchController"),
        ("/dashboard_client/play", "std_srvs/srv/Trigger"),
        ("/io_and_status_controller/set_io", "ur_msgs/srv/SetIO"),
    ]
    # One column (the names; the type is written at the call): one call, as before.
    assert found["action_clients"] == [
        ("/jtc/follow_joint_trajectory", "control_msgs/action/FollowJointTrajectory"),
        ("/scaled_jtc/follow_joint_trajectory", "control_msgs/action/FollowJointTrajectory"),
    ]


def test_a_table_longer_than_the_contexts_kept_invents_no_pairing(tmp_path: Path) -> None:
    rows = "\n".join(f"        '/io/pin_{i}': {'SetIO' if i % 2 else 'Trigger'}," for i in range(12))
    found = _clients(_workspace(tmp_path, "SERVICES = {\n" + rows + "\n    }"))["clients"]
    assert len(found) == 12
    assert {t for _, t in found} == {None}  # which type goes with which name: not known
