"""Stands in for the C++ wheel controller when there is no hardware."""
import rclpy
from nav_msgs.msg import Odometry
from rclpy.node import Node


class FakeWheelController(Node):

    def __init__(self):
        super().__init__('wheel_controller')
        self.declare_parameter('publish_rate', 20.0)
        rate = self.get_parameter('publish_rate').value
        self.odom_pub = self.create_publisher(Odometry, 'odom', 10)
        self.timer = self.create_timer(1.0 / rate, self.tick)

    def tick(self):
        self.odom_pub.publish(Odometry())


def main():
    rclpy.init()
    rclpy.spin(FakeWheelController())


if __name__ == '__main__':
    main()
