"""A text dashboard that listens to every sensor and status topic."""
import rclpy
from nav_msgs.msg import Odometry
from rclpy.node import Node
from sensor_msgs.msg import BatteryState, Image, LaserScan
from std_msgs.msg import String

from robot_base.names import ODOM_TOPIC, ROBOT_NAMESPACE, SCAN_TOPIC
from robot_base.qos import SCAN_QOS


class Dashboard(Node):
    """Keeps the latest reading of each topic and logs a summary."""

    IMAGE_TOPIC = 'image_raw'
    SUMMARY_PERIOD = 5.0  # seconds

    def __init__(self) -> None:
        super().__init__('dashboard')
        self._latest: dict[str, str] = {}
        robot = ROBOT_NAMESPACE
        battery_state_topic = f'/{robot}/battery_state'
        battery_status_topic = '/' + robot + '/battery_monitor/status'
        self.create_subscription(LaserScan, SCAN_TOPIC, self.on_scan, SCAN_QOS)
        self.create_subscription(Odometry, ODOM_TOPIC, self.on_odom, 10)
        self.create_subscription(Image, self.IMAGE_TOPIC, self.on_image, 10)
        self.create_subscription(
            BatteryState, battery_state_topic, self.on_battery, 10)
        self.create_subscription(
            String, battery_status_topic, self.on_battery_status, 10)
        self.create_subscription(
            String, '/lidar_driver/status', self.on_lidar_status, 10)
        self.create_subscription(
            String, '/motor_driver/status', self.on_motor_status, 10)
        self.create_timer(self.SUMMARY_PERIOD, self.log_summary)

    def on_scan(self, msg: LaserScan) -> None:
        self._latest['scan'] = f'{min(msg.ranges, default=0.0):.2f} m'

    def on_odom(self, msg: Odometry) -> None:
        self._latest['speed'] = f'{msg.twist.twist.linear.x:.2f} m/s'

    def on_image(self, msg: Image) -> None:
        self._latest['image'] = f'{msg.width}x{msg.height}'

    def on_battery(self, msg: BatteryState) -> None:
        self._latest['battery'] = f'{msg.percentage:.0%}'

    def on_battery_status(self, msg: String) -> None:
        self._latest['battery status'] = msg.data

    def on_lidar_status(self, msg: String) -> None:
        self._latest['lidar'] = msg.data

    def on_motor_status(self, msg: String) -> None:
        self._latest['motors'] = msg.data

    def log_summary(self) -> None:
        summary = ', '.join(
            f'{key}: {value}' for key, value in sorted(self._latest.items()))
        self.get_logger().info(summary or 'no data yet')


def main(args=None):
    rclpy.init(args=args)
    node = Dashboard()
    try:
        rclpy.spin(node)
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
