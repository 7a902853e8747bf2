"""Start the four thesis nodes in one process, as Code 6.7's ``main`` does.

Unlike the thesis listing, the nodes are spun by an executor so that their
timers and subscriptions actually run.
"""
import rclpy
from rclpy.executors import SingleThreadedExecutor

from thesis_graph.consumers import ROSNode3, ROSNode4
from thesis_graph.producers import ROSNode1, ROSNode2


def main(args=None):
    rclpy.init(args=args)
    nodes = [ROSNode1(), ROSNode2(), ROSNode3(), ROSNode4()]
    executor = SingleThreadedExecutor()
    for node in nodes:
        executor.add_node(node)
    try:
        executor.spin()
    finally:
        for node in nodes:
            node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
