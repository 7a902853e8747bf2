import rclpy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rclpy.node import Node
from sensor_msgs.msg import BatteryState


class BaseDriver(Node):
    def __init__(self):
        super().__init__('base_driver')
        self.odom_pub = self.create_publisher(Odometry, 'odom', 10)
        self.battery_pub = self.create_publisher(BatteryState, 'battery_state', 10)
        self.create_subscription(Twist, 'cmd_vel', self.on_cmd_vel, 10)
        self.create_timer(0.1, self.on_timer)

    def on_cmd_vel(self, msg):
        self.get_logger().info(f'driving at {msg.linear.x} m/s')

    def on_timer(self):
        self.odom_pub.publish(Odometry())
        battery = BatteryState()
        battery.percentage = 87
        self.battery_pub.publish(battery)


def main():
    rclpy.init()
    rclpy.spin(BaseDriver())
