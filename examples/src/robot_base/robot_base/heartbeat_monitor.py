"""Watch the heartbeats of all drivers and warn about silent ones."""
import rclpy
from rclpy.node import Node
from rclpy.time import Time
from std_msgs.msg import String

from robot_base.names import HEARTBEAT_TOPIC
from robot_base.qos import HEARTBEAT_QOS


class HeartbeatMonitor(Node):
    """Remembers when each driver last spoke; complains after a timeout."""

    CHECK_PERIOD = 2.0  # seconds
    TIMEOUT_NS = 3 * 10**9

    def __init__(self) -> None:
        super().__init__('heartbeat_monitor')
        self._last_seen: dict[str, Time] = {}
        self.create_subscription(
            String, HEARTBEAT_TOPIC, self.on_heartbeat, HEARTBEAT_QOS)
        self.create_timer(self.CHECK_PERIOD, self.check_stale)

    def on_heartbeat(self, msg: String) -> None:
        self._last_seen[msg.data] = self.get_clock().now()

    def check_stale(self) -> None:
        now = self.get_clock().now()
        for driver, seen in sorted(self._last_seen.items()):
            if (now - seen).nanoseconds > self.TIMEOUT_NS:
                self.get_logger().warn(f'{driver} is silent')


def main(args=None):
    rclpy.init(args=args)
    node = HeartbeatMonitor()
    try:
        rclpy.spin(node)
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
