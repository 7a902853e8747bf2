"""Nodes in namespaces: private (~), relative and absolute names."""
import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from sensor_msgs.msg import LaserScan, PointCloud2
from std_msgs.msg import String
from std_srvs.srv import Trigger


class Scanner(Node):

    def __init__(self):
        super().__init__('scanner', namespace='/robot2')
        self.create_publisher(LaserScan, 'scan', 10)
        self.create_publisher(PointCloud2, '~/points', 10)


def main(args=None):
    rclpy.init(args=args)
    node = Node('status_reporter', namespace='robot1')
    node.create_publisher(String, '~/status', 10)
    node.create_publisher(String, 'odom_text', 10)
    node.create_publisher(String, '/global_status', 10)

    def on_cmd(msg):
        node.get_logger().info(msg.data)

    def on_reset(request, response):
        response.success = True
        return response

    node.create_subscription(String, 'cmd', on_cmd, 10)
    node.create_service(Trigger, '~/reset', on_reset)
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    executor.add_node(Scanner())
    executor.spin()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
