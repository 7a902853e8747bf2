"""node_1 and node_2 of the thesis's four-node, eight-topic example."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class FirstNode(Node):

    def __init__(self):
        super().__init__('node_1')
        self.create_subscription(String, 'topic1', self.on_message, 10)  # ROS002
        self.create_subscription(String, 'topic3', self.on_message, 10)
        self.pub_7 = self.create_publisher(String, 'topic7', 10)
        self.pub_1 = self.create_publisher(String, 'topic1', 10)

    def on_message(self, msg):
        self.pub_7.publish(msg)


class SecondNode(Node):

    def __init__(self):
        super().__init__('node_2')
        self.pub_1 = self.create_publisher(String, 'topic1', 10)
        self.pub_2 = self.create_publisher(String, 'topic2', 10)
        self.pub_3 = self.create_publisher(String, 'topic3', 10)
        self.pub_4 = self.create_publisher(String, 'topic4', 10)
        self.pub_5 = self.create_publisher(String, 'topic5', 10)  # ROS001
        self.pub_6 = self.create_publisher(String, 'topic6', 10)
        self.pub_7 = self.create_publisher(String, 'topic7', 10)
        self.create_subscription(String, 'topic7', self.on_topic7, 10)  # ROS002
        self.timer = self.create_timer(0.5, self.on_timer)

    def on_timer(self):
        msg = String()
        msg.data = 'tick'
        for pub in (self.pub_1, self.pub_2, self.pub_3, self.pub_4, self.pub_5, self.pub_6):
            pub.publish(msg)

    def on_topic7(self, msg):
        self.get_logger().info(msg.data)


def main_node_1(args=None):
    rclpy.init(args=args)
    rclpy.spin(FirstNode())
    rclpy.shutdown()


def main_node_2(args=None):
    rclpy.init(args=args)
    rclpy.spin(SecondNode())
    rclpy.shutdown()
