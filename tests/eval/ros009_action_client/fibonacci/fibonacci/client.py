"""Sends a Fibonacci goal, to a misspelt action name."""
import rclpy
from example_interfaces.action import Fibonacci
from rclpy.action import ActionClient
from rclpy.node import Node


class FibonacciClient(Node):

    def __init__(self):
        super().__init__('fibonacci_client')
        self.client = ActionClient(self, Fibonacci, 'fibonaci')  # ROS009

    def send(self, order):
        goal = Fibonacci.Goal()
        goal.order = order
        self.client.wait_for_server()
        return self.client.send_goal_async(goal)


def main(args=None):
    rclpy.init(args=args)
    node = FibonacciClient()
    rclpy.spin_until_future_complete(node, node.send(10))
    rclpy.shutdown()
