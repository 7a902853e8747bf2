import rclpy
from example_interfaces.srv import AddTwoInts
from rclpy.node import Node
from std_srvs.srv import Trigger


class AddTwoIntsServer(Node):

    def __init__(self):
        super().__init__('add_two_ints_server')
        self.srv = self.create_service(
            AddTwoInts, 'add_two_ints', self.add_two_ints_callback)
        self.create_service(Trigger, '~/reset', self.reset_callback)
        self.calls = 0

    def add_two_ints_callback(self, request, response):
        self.calls += 1
        response.sum = request.a + request.b
        return response

    def reset_callback(self, request, response):
        self.calls = 0
        response.success = True
        return response


def main(args=None):
    rclpy.init(args=args)
    node = AddTwoIntsServer()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
