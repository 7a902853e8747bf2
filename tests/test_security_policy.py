"""ROS206: a delivery robot secured with SROS2. Its policy (policies/delivery.policy.xml, with
sros2's common/node.xml include and one of its own) grants the base driver its command input
and odometry, the planner its goal service and the dock action. The driver's odometry renamed
in code but not in the policy, a DENY rule the node trips over, and a client the planner's
profile never grants are reported; what the profiles grant (relative, ``~/`` and wildcard names,
an included rule file) is quiet, and so is a profile with an include that cannot be read (a
diagnostic names the include)."""
from __future__ import annotations

from pathlib import Path

from test_recall_globals_and_escapes import package
from test_workspace_discovery import write

from flake8_rosgraph.analysis import build_graph
from flake8_rosgraph.cache import build_report
from flake8_rosgraph.options import Settings

DRIVER = """
    import rclpy
    from geometry_msgs.msg import Twist
    from nav_msgs.msg import Odometry
    from rclpy.node import Node
    from sensor_msgs.msg import BatteryState, Imu

    WHEELS = ['left', 'right']


    class BaseDriver(Node):
        def __init__(self):
            super().__init__('base_driver', namespace='robot')
            self.create_subscription(Twist, 'cmd_vel', self.on_cmd, 10)
            self.odom = self.create_publisher(Odometry, 'odometry', 10)
            self.create_publisher(BatteryState, '~/battery', 10)
            for wheel in WHEELS:
                self.create_publisher(Imu, f'wheels/{wheel}/imu', 10)
            self.create_publisher(Imu, 'wheels/debug/imu', 10)

        def on_cmd(self, msg):
            self.odom.publish(Odometry())


    def main():
        rclpy.init()
        rclpy.spin(BaseDriver())
"""
PLANNER = """
    import rclpy
    from nav2_msgs.action import DockRobot
    from rclpy.action import ActionClient
    from rclpy.node import Node
    from std_srvs.srv import Trigger


    class Planner(Node):
        def __init__(self):
            super().__init__('planner', namespace='robot')
            self.create_service(Trigger, 'plan', self.on_plan)
            self.dock = ActionClient(self, DockRobot, 'dock_robot')
            self.reset = self.create_client(Trigger, '/robot/reset_odometry')

        def on_plan(self, request, response):
            response.success = True
            return response


    def main():
        rclpy.init()
        rclpy.spin(Planner())
"""
POLICY = """
    <?xml version="1.0" encoding="UTF-8"?>
    <policy version="0.2.0" xmlns:xi="http://www.w3.org/2001/XInclude">
      <enclaves>
        <enclave path="/delivery/base">
          <profiles>
            <profile ns="/robot" node="base_driver">
              <xi:include href="common/node.xml" xpointer="xpointer(/profile/*)"/>
              <topics subscribe="ALLOW"><topic>cmd_vel</topic></topics>
              <topics publish="ALLOW">
                <topic>odom</topic>
                <topic>~/battery</topic>
                <topic>wheels/*/imu</topic>
              </topics>
              <topics publish="DENY"><topic>wheels/debug/*</topic></topics>
            </profile>
          </profiles>
        </enclave>
        <enclave path="/delivery/planning">
          <profiles>
            <profile ns="/robot" node="planner">
              <xi:include href="common/node.xml" xpointer="xpointer(/profile/*)"/>
              <xi:include href="planner_actions.xml" xpointer="xpointer(/profile/*)"/>
              <services reply="ALLOW"><service>plan</service></services>
            </profile>
          </profiles>
        </enclave>
      </enclaves>
    </policy>
"""
PLANNER_ACTIONS = """
    <?xml version="1.0" encoding="UTF-8"?>
    <profile>
      <actions call="ALLOW"><action>dock_robot</action></actions>
    </profile>
"""
ENTRIES = "'driver = delivery.driver:main', 'planner = delivery.planner:main'"


def _findings(tmp_path: Path, policy: str = POLICY, actions: str | None = PLANNER_ACTIONS) -> list[tuple[str, int]]:
    files = package("delivery", ENTRIES, {"driver": DRIVER, "planner": PLANNER})
    files["delivery/policies/delivery.policy.xml"] = policy
    if actions is not None:
        files["delivery/policies/planner_actions.xml"] = actions
    report = build_report(write(tmp_path, files), Settings())
    return sorted((Path(f.location.path).name, f.location.line, f.message.split("'")[1])
                  for f in report.findings if f.code == "ROS206")


def test_endpoints_the_policy_does_not_grant_are_reported(tmp_path: Path) -> None:
    assert _findings(tmp_path) == [
        ("driver.py", 14, "/robot/odometry"),           # renamed in code, not in the policy
        ("driver.py", 18, "/robot/wheels/debug/imu"),   # a DENY rule wins over the ALLOW pattern
        ("planner.py", 13, "/robot/reset_odometry"),    # no request permission for it
    ]


def test_a_policy_granting_what_the_code_makes_is_quiet(tmp_path: Path) -> None:
    policy = POLICY.replace("<topic>odom</topic>", "<topic>odometry</topic>").replace(
        "<topics publish=\"DENY\"><topic>wheels/debug/*</topic></topics>", "").replace(
        "<services reply=\"ALLOW\"><service>plan</service></services>",
        "<services reply=\"ALLOW\"><service>plan</service></services>"
        "<services request=\"ALLOW\"><service>reset_odometry</service></services>")
    assert _findings(tmp_path, policy) == []


def test_a_profile_with_an_include_that_cannot_be_read_is_not_judged(tmp_path: Path) -> None:
    """The planner's action rules are missing: they may grant anything, the planner is not
    judged; the driver's profile is."""
    assert [name for _, _, name in _findings(tmp_path, actions=None)] == [
        "/robot/odometry", "/robot/wheels/debug/imu"]
    said = [d for d in build_graph(tmp_path).diagnostics if "planner_actions.xml" in d.message]
    assert [(d.path, d.line, d.severity) for d in said] == [("delivery/policies/delivery.policy.xml", 22, "info")]
