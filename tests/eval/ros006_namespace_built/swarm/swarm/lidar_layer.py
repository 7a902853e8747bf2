"""A robot's range layer from its lidar; the launch file picks the layer from the robot's sensor."""
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import LaserScan
from std_msgs.msg import Float32


class LidarLayer(Node):

    def __init__(self):
        super().__init__('lidar_layer')
        self.create_subscription(LaserScan, self.get_namespace() + '/scan', self.on_scan, 10)
        self.range_pub = self.create_publisher(Float32, self.get_namespace() + '/range_data', 10)

    def on_scan(self, msg):
        self.range_pub.publish(Float32(data=min(msg.ranges)))


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(LidarLayer())
