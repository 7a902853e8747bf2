"""Serves the map, but publishes it volatile: late subscribers never get it."""
import rclpy
from nav_msgs.msg import OccupancyGrid
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile


class MapServer(Node):

    def __init__(self):
        super().__init__('map_server')
        qos = QoSProfile(depth=1, durability=DurabilityPolicy.VOLATILE)
        self.map_pub = self.create_publisher(OccupancyGrid, 'map', qos)
        self.map_pub.publish(OccupancyGrid())


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(MapServer())
    rclpy.shutdown()
