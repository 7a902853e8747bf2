import rclpy
from rclpy.executors import SingleThreadedExecutor

from .drone import Drone
from .rover import Rover


def main(args=None):
    rclpy.init(args=args)
    executor = SingleThreadedExecutor()
    executor.add_node(Rover())
    executor.add_node(Drone())
    executor.spin()
    rclpy.shutdown()
