"""A node built with rclpy.create_node, callbacks as closures and lambdas."""
import rclpy
from std_msgs.msg import String


def main(args=None):
    rclpy.init(args=args)
    node = rclpy.create_node('functional_talker')
    publisher = node.create_publisher(String, 'chatter', 10)
    count = 0

    def timer_callback():
        nonlocal count
        count += 1
        publisher.publish(String(data='hello %d' % count))

    node.create_timer(0.5, timer_callback)
    node.create_timer(2.0, lambda: node.get_logger().info('alive'))
    node.create_subscription(
        String, 'commands', lambda msg: node.get_logger().info(msg.data), 10)
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
