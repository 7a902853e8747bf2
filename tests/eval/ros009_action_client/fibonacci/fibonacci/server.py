"""Serves the Fibonacci action."""
import rclpy
from example_interfaces.action import Fibonacci
from rclpy.action import ActionServer
from rclpy.node import Node


class FibonacciServer(Node):

    def __init__(self):
        super().__init__('fibonacci_server')
        self.server = ActionServer(self, Fibonacci, 'fibonacci', self.execute)

    def execute(self, goal_handle):
        result = Fibonacci.Result()
        result.sequence = [0, 1]
        goal_handle.succeed()
        return result


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(FibonacciServer())
    rclpy.shutdown()
