import sys

import rclpy
from diagnostic_msgs.msg import DiagnosticStatus
from drive_interfaces.msg import WheelCommand, WheelSpeeds
from geometry_msgs.msg import Point, Pose, PoseStamped, Twist
from rclpy.node import Node
from sensor_msgs.msg import BatteryState, JointState, LaserScan
from std_msgs.msg import Bool, Header, Int32, String

from drive_base.commands import make_stop, make_twist


class Driver(Node):

    def __init__(self):
        super().__init__('driver')
        self.cmd_pub = self.create_publisher(Twist, 'cmd_vel', 10)
        self.speed = self.declare_parameter('speed', 0.5).value
        self.create_timer(0.1, self.on_tick)

    def on_tick(self):
        self.cmd_pub.publish(make_twist(1, 0.5))
        self.cmd_pub.publish(make_stop())
        cmd = Twist()
        cmd.linear.x = self.speed
        cmd.linear.X = 1.0  # ROS107
        cmd.angular.z = float(sys.argv[1])

        header = Header()
        header.stamp = self.get_clock().now()  # ROS107
        header.stamp = self.get_clock().now().to_msg()
        header.frame_id = 'base_link'

        status = DiagnosticStatus()
        status.level = 2  # ROS107
        status.level = DiagnosticStatus.ERROR
        battery = BatteryState()
        battery.power_supply_status = 300  # ROS107
        battery.power_supply_status = BatteryState.POWER_SUPPLY_STATUS_CHARGING
        battery.percentage = 0.5

        scan = LaserScan()
        scan.ranges = 0.0  # ROS107
        scan.ranges = [0.0] * 360
        joints = JointState()
        joints.position = [0, 0]  # ROS107
        joints.position = [0.0, 0.0]

        pose = PoseStamped()
        pose.pose = Point()  # ROS107
        pose.pose = Pose()
        pose.header = header

        texts = [String(dat='typo'),  # ROS107
                 String('positional'),  # ROS107
                 String(data='fine')]
        numbers = [Int32(data='5'),  # ROS107
                   Int32(data=True),
                   Int32(data=7)]
        flags = [Bool(data=1),  # ROS107
                 Bool(data=False)]
        return texts, numbers, flags

    def report(self):
        speeds = WheelSpeeds()
        speeds.left = 1  # ROS107
        speeds.right = 1.0
        speeds.mode = 256  # ROS107
        speeds.mode = WheelSpeeds.MODE_DRIVE
        speeds.label = 'front-left'  # ROS107
        speeds.label = 'front'
        speeds.header.stamp = self.get_clock().now().to_msg()
        speeds.header.frame_id = 7  # ROS107
        speeds.last_command = WheelCommand(targets=(1.0, 2.0, 3.0))  # ROS107
        speeds.last_command = WheelCommand(targets=(1.0, 2.0))
        self.get_logger().info(f'left {speeds.left} in mode {speeds.mode}')
        self.get_logger().info(f'stamp {speeds.header.stamp.sec} {speeds.header.stamp.nanosec}')
        self.get_logger().info(f'right {speeds.rigth}')  # ROS107
        self.get_logger().info(f'{speeds.header.stamp.secs}')  # ROS107
        fields = speeds.get_fields_and_field_types()
        idle = speeds.MODE_IDLE
        return speeds, fields, idle


def main(args=None):
    rclpy.init(args=args)
    driver = Driver()
    driver.report()
    rclpy.spin(driver)
