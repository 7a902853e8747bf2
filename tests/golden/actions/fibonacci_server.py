import rclpy
import rclpy.action
from example_interfaces.action import Fibonacci
from rclpy.node import Node


class FibonacciActionServer(Node):

    def __init__(self):
        super().__init__('fibonacci_action_server')
        self._action_server = rclpy.action.ActionServer(
            self, Fibonacci, 'fibonacci', execute_callback=self.cb)
        self._slow_server = rclpy.action.ActionServer(
            self, Fibonacci, '~/slow_fibonacci', self.execute_slowly)

    def cb(self, goal_handle):
        return self.compute(goal_handle, publish_every=1)

    def execute_slowly(self, goal_handle):
        return self.compute(goal_handle, publish_every=5)

    def compute(self, goal_handle, publish_every):
        sequence = [0, 1]
        feedback = Fibonacci.Feedback()
        for i in range(1, goal_handle.request.order):
            sequence.append(sequence[i] + sequence[i - 1])
            if i % publish_every == 0:
                feedback.sequence = sequence
                goal_handle.publish_feedback(feedback)
        goal_handle.succeed()
        result = Fibonacci.Result()
        result.sequence = sequence
        return result


def main(args=None):
    rclpy.init(args=args)
    node = FibonacciActionServer()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
