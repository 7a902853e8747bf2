"""The robot's base driver: odometry, battery and IMU for whoever listens (rviz, a bag, the
fleet), joint states for the workspace, and a trajectory action served by a second node."""
import rclpy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from sensor_msgs.msg import BatteryState, Imu, JointState
from std_msgs.msg import Bool


class TrajectoryServer(Node):
    def __init__(self, driver):
        super().__init__('trajectory_server')
        self.driver = driver
        self.create_subscription(Bool, 'trajectory_enable', self.on_enable, 1)

    def on_enable(self, msg):
        self.driver.enabled = msg.data


class Driver(Node):
    def __init__(self):
        super().__init__('base_driver')
        self.enabled = True
        self.odom = self.create_publisher(Odometry, 'odom', 10)
        self.battery = self.create_publisher(BatteryState, 'battery', 1)
        self.imu = self.create_publisher(Imu, 'imu', 10)
        self.states = self.create_publisher(JointState, 'wheel_states', 10)
        self.create_subscription(Twist, 'cmd_vel', self.on_cmd, 1)
        self.create_timer(0.05, self.tick)

    def on_cmd(self, msg):
        self.get_logger().debug(f'{msg.linear.x}')

    def tick(self):
        self.odom.publish(Odometry())
        self.battery.publish(BatteryState(percentage=0.9))
        self.imu.publish(Imu())
        self.states.publish(JointState(name=['left', 'right']))


def main(args=None):
    rclpy.init(args=args)
    driver = Driver()
    executor = MultiThreadedExecutor()
    executor.add_node(driver)
    executor.add_node(TrajectoryServer(driver))
    executor.spin()
