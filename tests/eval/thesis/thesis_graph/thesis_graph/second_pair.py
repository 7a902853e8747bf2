"""node_3 and node_4 of the thesis's four-node, eight-topic example."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class ThirdNode(Node):

    def __init__(self):
        super().__init__('node_3')
        self.create_subscription(String, 'topic2', self.on_message, 10)
        self.create_subscription(String, 'topic3', self.on_message, 10)
        self.create_subscription(String, 'topic6', self.on_message, 10)
        self.create_subscription(String, 'topic7', self.on_message, 10)
        self.create_subscription(String, 'topic4', self.on_message, 10)
        self.create_subscription(String, 'topic8', self.on_message, 10)  # ROS003

    def on_message(self, msg):
        self.get_logger().info(msg.data)


class FourthNode(Node):

    def __init__(self):
        super().__init__('node_4')
        self.pub_1 = self.create_publisher(String, 'topic1', 10)
        self.pub_3 = self.create_publisher(String, 'topic3', 10)
        self.create_subscription(String, 'topic2', self.on_topic2, 10)

    def on_topic2(self, msg):
        self.pub_1.publish(msg)
        self.pub_3.publish(msg)


def main_node_3(args=None):
    rclpy.init(args=args)
    rclpy.spin(ThirdNode())
    rclpy.shutdown()


def main_node_4(args=None):
    rclpy.init(args=args)
    rclpy.spin(FourthNode())
    rclpy.shutdown()
