"""The ways a Node subclass can call the Node constructor."""
import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from std_msgs.msg import String


class KeywordNode(Node):

    def __init__(self):
        super().__init__(node_name='keyword_node')
        self.create_publisher(String, 'keyword_out', 10)


class ExplicitSuperNode(Node):

    def __init__(self):
        super(ExplicitSuperNode, self).__init__(
            'explicit_super_node', namespace='legacy')
        self.create_publisher(String, 'legacy_out', 10)


class DirectInitNode(Node):

    def __init__(self):
        Node.__init__(self, 'direct_init_node')
        self.create_publisher(String, 'direct_out', 10)


def main(args=None):
    rclpy.init(args=args)
    executor = SingleThreadedExecutor()
    for node in (KeywordNode(), ExplicitSuperNode(), DirectInitNode()):
        executor.add_node(node)
    executor.spin()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
