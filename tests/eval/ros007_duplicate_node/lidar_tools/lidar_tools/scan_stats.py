"""Scan statistics, with a second node for parameter calls that must not block the first."""
import rclpy
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from sensor_msgs.msg import LaserScan


class ScanStats(Node):
    def __init__(self, name):
        super().__init__(name)
        self.create_subscription(LaserScan, 'scan_filtered', self.on_scan, 10)

    def on_scan(self, msg):
        self.get_logger().info(str(min(msg.ranges)))


def helper_node(parent, pinned):
    """The helper keeps its own name under a launch ``name`` only when its arguments pin it."""
    helper_name = f'{parent}_params'
    if pinned:
        return rclpy.create_node(helper_name, cli_args=['--ros-args', '-r', f'__node:={helper_name}'],
                                 start_parameter_services=False)
    return rclpy.create_node(helper_name, start_parameter_services=False)


def run(name, pinned):
    rclpy.init()
    executor = MultiThreadedExecutor()
    executor.add_node(ScanStats(name))
    executor.add_node(helper_node(name, pinned))
    executor.spin()


def main():
    run('scan_stats', pinned=True)


def dump_main():
    run('scan_dump', pinned=False)
