"""A base class for the robot's drivers: every driver sends a heartbeat.

The heartbeat publisher, its timer and the ``robot_id`` parameter are created
in ``__init__`` here, so every subclass (in other packages) gets them.
"""
from rclpy.node import Node
from std_msgs.msg import String

from robot_base.names import HEARTBEAT_TOPIC
from robot_base.qos import HEARTBEAT_QOS


class ManagedNode(Node):
    """A node that announces itself on ``/heartbeat`` once per period."""

    HEARTBEAT_PERIOD = 1.0  # seconds

    def __init__(self, node_name: str) -> None:
        super().__init__(node_name)
        self.declare_parameter('robot_id', 'robot1')
        self._heartbeat_pub = self.create_publisher(
            String, HEARTBEAT_TOPIC, HEARTBEAT_QOS)
        self._heartbeat_timer = self.create_timer(
            self.HEARTBEAT_PERIOD, self._publish_heartbeat)

    def _publish_heartbeat(self) -> None:
        msg = String()
        robot_id = self.get_parameter('robot_id').value
        msg.data = f'{robot_id}/{self.get_name()}'
        self._heartbeat_pub.publish(msg)
