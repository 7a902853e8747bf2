"""The start pose comes from parameters the launch file sets: their declared defaults are not the values."""
import rclpy
from geometry_msgs.msg import Point
from rclpy.node import Node


class SimPose(Node):
    def __init__(self):
        super().__init__('sim_pose')
        self.declare_parameter('sx')          # no default: the launch file's parameter file sets it
        self.declare_parameter('sy', None)
        self.start = [self.get_parameter('sx').value, self.get_parameter('sy').value]
        self.pub = self.create_publisher(Point, 'start_point', 10)
        self.create_timer(1.0, self.tick)

    def tick(self):
        point = Point()
        point.x = self.start[0]
        point.y = self.start[1]
        point.z = None  # ROS107
        self.pub.publish(point)


def main():
    rclpy.init()
    rclpy.spin(SimPose())
