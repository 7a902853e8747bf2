import rclpy
from example_interfaces.srv import AddTwoInts
from rclpy.node import Node
from std_srvs.srv import Trigger


class AddTwoIntsClient(Node):

    def __init__(self):
        super().__init__('add_two_ints_client')
        self.add_client = self.create_client(AddTwoInts, 'add_two_ints')
        self.reset_client = self.create_client(
            Trigger, '/add_two_ints_server/reset')

    def send_request(self, a, b):
        request = AddTwoInts.Request()
        request.a = a
        request.b = b
        return self.add_client.call_async(request)


def main(args=None):
    rclpy.init(args=args)
    node = AddTwoIntsClient()
    node.add_client.wait_for_service()
    future = node.send_request(2, 3)
    rclpy.spin_until_future_complete(node, future)
    node.get_logger().info('sum: %d' % future.result().sum)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
