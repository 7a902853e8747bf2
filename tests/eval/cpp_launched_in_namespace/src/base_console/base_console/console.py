"""Operator console: talks to the C++ wheel controller that base_bringup starts in /base."""
import rclpy
from nav_msgs.msg import Odometry
from rclpy.node import Node
from sensor_msgs.msg import BatteryState
from std_srvs.srv import Trigger

BASE_NS = '/base'


class Console(Node):

    def __init__(self):
        super().__init__('console')
        # Served by the C++ node: its relative 'reset_odometry' runs in the launch namespace /base.
        self.reset_client = self.create_client(Trigger, BASE_NS + '/reset_odometry')
        self.odom_sub = self.create_subscription(Odometry, BASE_NS + '/odom', self.on_odom, 10)
        # A slip of the pen beside the served name is still one.
        self.home_client = self.create_client(Trigger, BASE_NS + '/reset_odometyr')  # ROS008
        # The battery driver is an installed package the launch file starts in /power.
        self.battery_sub = self.create_subscription(BatteryState, '/power/battery_state', self.on_battery, 10)
        # Nothing serves this, and nothing the launch file starts lives under /base but the controller.
        self.dock_client = self.create_client(Trigger, BASE_NS + '/start_docking')  # ROS008
        self.timer = self.create_timer(1.0, self.tick)

    def on_odom(self, msg):
        self.get_logger().info(f'x={msg.pose.pose.position.x}')

    def on_battery(self, msg):
        self.get_logger().info(f'battery {msg.percentage}')

    def tick(self):
        if self.reset_client.service_is_ready():
            self.reset_client.call_async(Trigger.Request())


def main():
    rclpy.init()
    rclpy.spin(Console())


if __name__ == '__main__':
    main()
