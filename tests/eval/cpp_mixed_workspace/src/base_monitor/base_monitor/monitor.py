"""Watches the C++ base driver: odometry, battery, status, diagnostics; docks the robot."""
import rclpy
from geometry_msgs.msg import Twist
from nav2_msgs.action import DockRobot
from nav_msgs.msg import Odometry
from rclpy.action import ActionClient
from rclpy.node import Node
from std_msgs.msg import Bool, Float32, String
from std_srvs.srv import Trigger

from base_monitor.topics import ODOM, RESET_SERVICE, STATUS


class BaseMonitor(Node):

    def __init__(self):
        super().__init__('base_monitor')
        # Published by the C++ driver (a parameter default, a constexpr) and the damaged docking file.
        self.create_subscription(Odometry, ODOM, self.on_odom, 10)
        self.create_subscription(String, STATUS, self.on_status, 10)
        self.create_subscription(Bool, 'is_charging', self.on_charging, 1)
        # The driver publishes sensor_msgs/BatteryState here.
        self.create_subscription(Float32, 'battery', self.on_battery, 5)  # ROS004
        # The C++ aggregator misspells this topic ('diagnostic_summary').
        self.create_subscription(String, 'diagnostics_summary', self.on_summary, 10)  # ROS003
        self.create_subscription(String, 'alert_ack', self.on_ack, 10)
        self.alerts = self.create_publisher(String, 'alerts', 10)
        # Nobody listens: the C++ IMU subscription with an unknown name cannot be it (other type).
        self.limit = self.create_publisher(Twist, 'speed_limit_cmd', 10)  # ROS001
        self.reset = self.create_client(Trigger, RESET_SERVICE)
        self.dock = ActionClient(self, DockRobot, 'dock_robot')

    def on_odom(self, msg):
        self.limit.publish(Twist())

    def on_status(self, msg):
        self.alerts.publish(msg)

    def on_charging(self, msg):
        pass

    def on_battery(self, msg):
        if msg.data < 0.1:
            self.dock.send_goal_async(DockRobot.Goal())

    def on_summary(self, msg):
        self.get_logger().info(msg.data)

    def on_ack(self, msg):
        pass


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(BaseMonitor())
    rclpy.shutdown()
