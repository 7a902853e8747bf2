import rclpy
from sensor_msgs.msg import LaserScan

from lidar_driver.sensor_base import SensorNode


class ScanDriver(SensorNode):

    def __init__(self):
        super().__init__('scan_driver')
        self.declare_parameter('frame_id', 'laser')
        self.scan_pub = self.create_publisher(LaserScan, self.output_topic('scan_topic', 'scan'), 10)  # ROS001
        self.timer = self.create_timer(0.1, self.tick)

    def tick(self):
        msg = LaserScan()
        msg.header.frame_id = self.get_parameter('frame_id').value
        self.scan_pub.publish(msg)


def main():
    rclpy.init()
    rclpy.spin(ScanDriver())
