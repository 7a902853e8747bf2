"""Serves missions on the framework's shared node."""
import rclpy
from example_interfaces.action import Fibonacci
from mission_core.shared_node import SharedNode
from rclpy.action import ActionServer


class MissionServer:

    def __init__(self, node):
        self.node = node
        self.server = ActionServer(node, Fibonacci, 'run_mission', self.execute)

    def execute(self, goal_handle):
        goal_handle.succeed()
        return Fibonacci.Result()


def main():
    rclpy.init()
    node = SharedNode.get_instance()
    MissionServer(node)
    rclpy.spin(node)


if __name__ == '__main__':
    main()
