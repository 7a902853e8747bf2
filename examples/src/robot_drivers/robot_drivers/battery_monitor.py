"""The battery monitor of robot1: a node in its own namespace.

``battery_state`` is relative, so it resolves to ``/robot1/battery_state``;
``~/status`` is private and resolves to ``/robot1/battery_monitor/status``.
"""
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import BatteryState
from std_msgs.msg import String

from robot_base.names import ROBOT_NAMESPACE


class BatteryMonitor(Node):
    """Samples the battery periodically and warns when the voltage is low."""

    def __init__(self) -> None:
        super().__init__('battery_monitor', namespace=ROBOT_NAMESPACE)
        self.declare_parameters(namespace='', parameters=[
            ('low_voltage', 10.5),
            ('full_voltage', 12.6),
        ])
        self._state_pub = self.create_publisher(
            BatteryState, 'battery_state', 10)
        self._status_pub = self.create_publisher(String, '~/status', 10)
        sample_period = 2.0  # seconds
        self.create_timer(sample_period, self.sample)

    def read_voltage(self) -> float:
        """Stand-in for the ADC read of a real driver."""
        return 12.1

    def sample(self) -> None:
        voltage = self.read_voltage()
        low = self.get_parameter('low_voltage').value
        full = self.get_parameter('full_voltage').value
        state = BatteryState()
        state.header.stamp = self.get_clock().now().to_msg()
        state.voltage = voltage
        state.percentage = min(1.0, max(0.0, (voltage - low) / (full - low)))
        self._state_pub.publish(state)
        status = String()
        status.data = 'low' if voltage < low else 'ok'
        self._status_pub.publish(status)


def main(args=None):
    rclpy.init(args=args)
    node = BatteryMonitor()
    try:
        rclpy.spin(node)
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
