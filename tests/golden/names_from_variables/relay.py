"""A relay whose topic names all come from variables of some kind."""
import rclpy
from rclpy.node import Node
from std_msgs.msg import String

DIAGNOSTICS_TOPIC = 'relay_diagnostics'


class Relay(Node):

    def __init__(self):
        super().__init__('relay')
        input_topic = 'raw_text'
        output_topic = input_topic
        output_topic = 'filtered_text'
        self.create_subscription(String, input_topic, self.on_raw, 10)
        self.output = self.create_publisher(String, output_topic, 10)
        self.create_publisher(String, DIAGNOSTICS_TOPIC, 10)
        self.echo_topic = 'echo_text'
        self.create_publisher(String, self.echo_topic, 10)
        left, right = 'left_text', 'right_text'
        self.create_subscription(String, left, self.on_raw, 10)
        self.create_subscription(String, right, self.on_raw, 10)

    def on_raw(self, msg):
        self.output.publish(msg)


def main(args=None):
    rclpy.init(args=args)
    node = Relay()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
