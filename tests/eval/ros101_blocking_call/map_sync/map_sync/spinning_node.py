import time

import rclpy
from nav_msgs.srv import GetMap
from rclpy.node import Node


class SpinningNode(Node):
    def __init__(self):
        super().__init__('spinning_map_sync')
        self.map_client = self.create_client(GetMap, 'map_server/map')
        self.create_timer(1.0, self.on_timer)
        self.create_timer(2.0, self.on_slow_timer)
        self.rate = self.create_rate(10)

    def on_timer(self):
        future = self.map_client.call_async(GetMap.Request())
        rclpy.spin_until_future_complete(self, future)  # ROS101

    def on_slow_timer(self):
        time.sleep(0.01)
        time.sleep(2.0)  # ROS101
        self.rate.sleep()  # ROS101


class HelperNodeSpinner(Node):
    """Legal: the helper node is spun by its own executor, not the one running the callback."""

    def __init__(self):
        super().__init__('helper_spinner')
        self.helper = rclpy.create_node('map_sync_helper')
        self.map_client = self.helper.create_client(GetMap, 'map_server/map')
        self.create_timer(1.0, self.on_timer)

    def on_timer(self):
        future = self.map_client.call_async(GetMap.Request())
        rclpy.spin_until_future_complete(self.helper, future)


def main():
    rclpy.init()
    node = SpinningNode()
    other = HelperNodeSpinner()
    rclpy.spin(node)
    rclpy.spin(other)
