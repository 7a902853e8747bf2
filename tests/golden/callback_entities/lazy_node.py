"""Entities created in callbacks: after start-up, and per received message."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class LazyNode(Node):

    def __init__(self):
        super().__init__('lazy_node')
        self.heartbeat_pub = None
        self.startup_timer = self.create_timer(1.0, self.on_startup)
        self.create_subscription(
            String, 'robot_announce', self.on_announce, 10)

    def on_startup(self):
        self.startup_timer.cancel()
        self.heartbeat_pub = self.create_publisher(String, 'heartbeat', 10)
        self.create_timer(0.5, self.on_heartbeat)

    def on_heartbeat(self):
        self.heartbeat_pub.publish(String(data='alive'))

    def on_announce(self, msg):
        self.create_publisher(String, '/' + msg.data + '/cmd', 10)
        self.create_subscription(
            String, 'robot_status', self.on_robot_status, 10)

    def on_robot_status(self, msg):
        self.get_logger().info(msg.data)


def main(args=None):
    rclpy.init(args=args)
    node = LazyNode()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
