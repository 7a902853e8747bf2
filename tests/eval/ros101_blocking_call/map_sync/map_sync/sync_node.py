import rclpy
from nav_msgs.msg import OccupancyGrid
from nav_msgs.srv import GetMap
from rclpy.node import Node
from std_msgs.msg import Empty

from map_sync import requests

MAP_SERVICE = 'map_server/map'


class SyncNode(Node):
    def __init__(self):
        super().__init__('map_sync')
        self.map_client = self.create_client(GetMap, MAP_SERVICE)
        self.map_pub = self.create_publisher(OccupancyGrid, 'map_copy', 1)
        self.create_subscription(Empty, 'map_updated', self.on_update, 10)

    def on_update(self, msg):
        response = requests.refresh(self)  # ROS101
        self.map_pub.publish(response.map)


def main():
    rclpy.init()
    node = SyncNode()
    rclpy.spin(node)
    rclpy.shutdown()
