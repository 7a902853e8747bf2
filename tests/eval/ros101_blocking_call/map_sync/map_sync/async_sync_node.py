import rclpy
from nav_msgs.msg import OccupancyGrid
from nav_msgs.srv import GetMap
from rclpy.node import Node
from std_msgs.msg import Empty


class AsyncSyncNode(Node):
    """The correct twin: call_async and a done callback, the executor stays free."""

    def __init__(self):
        super().__init__('async_map_sync')
        self.map_client = self.create_client(GetMap, 'map_server/map')
        self.map_pub = self.create_publisher(OccupancyGrid, 'map_copy', 1)
        self.create_subscription(Empty, 'map_updated', self.on_update, 10)

    def on_update(self, msg):
        future = self.map_client.call_async(GetMap.Request())
        future.add_done_callback(self.on_map)

    def on_map(self, future):
        self.map_pub.publish(future.result().map)


def main():
    rclpy.init()
    node = AsyncSyncNode()
    rclpy.spin(node)
