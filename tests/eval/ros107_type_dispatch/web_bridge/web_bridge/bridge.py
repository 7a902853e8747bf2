import json

import rclpy
from nav_msgs.msg import OccupancyGrid, Path
from rclpy.node import Node
from sensor_msgs.msg import Image, LaserScan, PointCloud2

from web_bridge.convert import to_dict

STREAMS = {
    'camera/image_raw': Image,
    'points': PointCloud2,
    'scan_filtered': LaserScan,
    'map': OccupancyGrid,
    'plan': Path,
}


class Bridge(Node):

    def __init__(self):
        super().__init__('web_bridge')
        self.sent = []
        self.create_subscription(Image, 'camera/image_raw', self.on_image, 5)
        self.create_subscription(Path, 'plan', self.on_plan, 5)
        self.create_subscription(LaserScan, 'scan', self.on_scan, 5)
        for topic, msg_type in STREAMS.items():
            self.create_subscription(msg_type, topic, self.on_any, 5)

    def on_image(self, msg):
        self.sent.append(json.dumps(to_dict(msg)))

    def on_plan(self, msg):
        self.sent.append(json.dumps(to_dict(msg)))

    def on_scan(self, msg):
        self.sent.append(json.dumps(to_dict(msg)))

    def on_any(self, msg):
        self.sent.append(json.dumps(to_dict(msg)))


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Bridge())


if __name__ == '__main__':
    # A smoke test of the converters on empty messages.
    print(to_dict(Path()))
    print(to_dict(LaserScan()))
