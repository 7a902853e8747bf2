import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data


class Keys(Node):
    def __init__(self):
        super().__init__('keys')
        self.pub = self.create_publisher(Twist, 'cmd_vel', qos_profile_sensor_data)
        self.create_timer(0.1, lambda: self.pub.publish(Twist()))


def main():
    rclpy.init()
    rclpy.spin(Keys())
