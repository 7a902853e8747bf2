"""Topic names taken from declared parameters (their defaults, statically)."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class ParamTalker(Node):

    def __init__(self):
        super().__init__('param_talker')
        self.declare_parameter('topic', 'chatter')
        self.declare_parameter('reply_topic', 'replies')
        topic = self.get_parameter('topic').value
        self.publisher = self.create_publisher(String, topic, 10)
        reply_topic = self.get_parameter(
            'reply_topic').get_parameter_value().string_value
        self.create_subscription(String, reply_topic, self.on_reply, 10)

    def on_reply(self, msg):
        self.get_logger().info('reply: %s' % msg.data)


def main(args=None):
    rclpy.init(args=args)
    node = ParamTalker()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
