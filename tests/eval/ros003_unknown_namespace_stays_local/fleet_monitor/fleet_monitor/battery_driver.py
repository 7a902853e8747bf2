"""One battery driver per robot: the robot's namespace comes from the command line."""
import sys

import rclpy
from rclpy.node import Node
from sensor_msgs.msg import BatteryState


class BatteryDriver(Node):

    def __init__(self, robot):
        super().__init__('battery_driver', namespace=robot)
        # Relative: '/<robot>/battery_state', for whichever robot it runs on.
        self.state_pub = self.create_publisher(BatteryState, 'battery_state', 10)
        self.create_timer(1.0, self.on_timer)

    def on_timer(self):
        self.state_pub.publish(BatteryState())


def main():
    rclpy.init()
    rclpy.spin(BatteryDriver(sys.argv[1]))
