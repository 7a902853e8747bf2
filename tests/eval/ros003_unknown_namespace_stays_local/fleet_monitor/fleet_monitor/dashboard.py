"""Shows the odometry and the batteries of the fleet."""
import rclpy
from nav_msgs.msg import Odometry
from rclpy.node import Node
from sensor_msgs.msg import BatteryState


class Dashboard(Node):

    def __init__(self):
        super().__init__('dashboard')
        self.create_subscription(Odometry, '/odom', self.on_odom, 10)
        # A battery driver started with robot1 publishes this one.
        self.create_subscription(BatteryState, '/robot1/battery_state', self.on_battery, 10)
        # Nothing publishes a voltage topic, whatever namespace a driver runs in.
        self.create_subscription(BatteryState, '/battery_voltage', self.on_battery, 10)  # ROS003

    def on_odom(self, msg):
        self.get_logger().info(str(msg.pose.pose.position.x))

    def on_battery(self, msg):
        self.get_logger().info(str(msg.percentage))


def main():
    rclpy.init()
    rclpy.spin(Dashboard())
