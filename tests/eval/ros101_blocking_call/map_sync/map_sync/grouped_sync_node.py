import rclpy
from nav_msgs.msg import OccupancyGrid
from nav_msgs.srv import GetMap
from rclpy.callback_groups import MutuallyExclusiveCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from std_msgs.msg import Empty

from map_sync.requests import fetch_map


class GroupedSyncNode(Node):
    """Legal: the client has its own group, and a MultiThreadedExecutor spins the node."""

    def __init__(self):
        super().__init__('grouped_map_sync')
        self.client_group = MutuallyExclusiveCallbackGroup()
        self.map_client = self.create_client(GetMap, 'map_server/map',
                                             callback_group=self.client_group)
        self.map_pub = self.create_publisher(OccupancyGrid, 'map_copy', 1)
        self.create_subscription(Empty, 'map_updated', self.on_update, 10)

    def on_update(self, msg):
        self.map_pub.publish(fetch_map(self.map_client).map)


class SameGroupNode(Node):
    """A MultiThreadedExecutor does not help when caller and client share one exclusive group."""

    def __init__(self):
        super().__init__('same_group_map_sync')
        group = MutuallyExclusiveCallbackGroup()
        self.map_client = self.create_client(GetMap, 'map_server/map', callback_group=group)
        self.create_subscription(Empty, 'map_updated', self.on_update, 10, callback_group=group)

    def on_update(self, msg):
        fetch_map(self.map_client)  # ROS101


def main():
    rclpy.init()
    executor = MultiThreadedExecutor()
    executor.add_node(GroupedSyncNode())
    executor.add_node(SameGroupNode())
    executor.spin()
