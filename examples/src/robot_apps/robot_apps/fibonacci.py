"""An action server computing Fibonacci sequences, and a client asking it."""
import rclpy
from example_interfaces.action import Fibonacci
from rclpy.action import ActionClient, ActionServer
from rclpy.node import Node


class FibonacciServer(Node):
    """Serves the ``fibonacci`` action, sending each new term as feedback."""

    def __init__(self) -> None:
        super().__init__('fibonacci_server')
        self._server = ActionServer(
            self, Fibonacci, 'fibonacci',
            execute_callback=self.execute_callback)

    def execute_callback(self, goal_handle):
        sequence = [0, 1]
        feedback = Fibonacci.Feedback()
        for i in range(1, goal_handle.request.order):
            sequence.append(sequence[i] + sequence[i - 1])
            feedback.sequence = sequence
            goal_handle.publish_feedback(feedback)
        goal_handle.succeed()
        result = Fibonacci.Result()
        result.sequence = sequence
        return result


class FibonacciClient(Node):
    """Sends one goal as soon as the server is up, then logs the feedback."""

    ORDER = 10

    def __init__(self) -> None:
        super().__init__('fibonacci_client')
        self._client = ActionClient(self, Fibonacci, 'fibonacci')
        self._goal_future = None
        self._timer = self.create_timer(0.5, self.try_send_goal)

    def try_send_goal(self) -> None:
        if self._goal_future is not None or not self._client.server_is_ready():
            return
        goal = Fibonacci.Goal()
        goal.order = self.ORDER
        self._goal_future = self._client.send_goal_async(
            goal, feedback_callback=self.on_feedback)
        self._timer.cancel()

    def on_feedback(self, feedback_msg) -> None:
        sequence = list(feedback_msg.feedback.sequence)
        self.get_logger().info(f'sequence so far: {sequence}')


def _spin(node: Node) -> None:
    try:
        rclpy.spin(node)
    finally:
        node.destroy_node()
        rclpy.shutdown()


def server_main(args=None):
    rclpy.init(args=args)
    _spin(FibonacciServer())


def client_main(args=None):
    rclpy.init(args=args)
    _spin(FibonacciClient())
