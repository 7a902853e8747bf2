"""Callbacks in reentrant groups, lambdas, action callbacks and separate executors."""
import rclpy
from action_msgs.msg import GoalStatus
from nav2_msgs.action import NavigateToPose
from nav_msgs.srv import GetMap
from rclpy.action import ActionClient, ActionServer
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor, SingleThreadedExecutor
from rclpy.node import Node


class ReentrantSync(Node):
    """Caller and client share one reentrant group: legal under a MultiThreadedExecutor."""

    def __init__(self, name):
        super().__init__(name)
        group = ReentrantCallbackGroup()
        self.map_client = self.create_client(GetMap, 'map_server/map', callback_group=group)
        self.create_timer(1.0, self.on_timer, callback_group=group)

    def on_timer(self):
        self.map_client.call(GetMap.Request())  # ROS101 -- for the instance rclpy.spin runs


class LambdaSync(Node):
    def __init__(self):
        super().__init__('lambda_sync')
        self.map_client = self.create_client(GetMap, 'map_server/map')
        self.create_timer(1.0, lambda: self.map_client.call(GetMap.Request()))  # ROS101


class OwnGroupSpunElsewhere(Node):
    """Spun by code outside this package: the executor may be multi-threaded, so a client in
    another group than the caller may be legal."""

    def __init__(self):
        super().__init__('spun_elsewhere')
        self.map_client = self.create_client(GetMap, 'map_server/map')
        self.create_timer(1.0, self.on_timer, callback_group=ReentrantCallbackGroup())

    def on_timer(self):
        self.map_client.call(GetMap.Request())


class Relay(Node):
    """An action server whose execute callback drives another action synchronously."""

    def __init__(self):
        super().__init__('relay')
        self.nav = ActionClient(self, NavigateToPose, 'navigate_to_pose')
        self.server = ActionServer(self, NavigateToPose, 'relay', self.execute)
        self.private_executor = SingleThreadedExecutor()
        self.worker = rclpy.create_node('relay_worker')
        self.private_executor.add_node(self.worker)
        self.create_timer(0.5, self.on_timer)

    def execute(self, goal_handle):
        result = self.nav.send_goal(goal_handle.request)  # ROS101
        if result.status == GoalStatus.STATUS_SUCCEEDED:
            goal_handle.succeed()
        return result.result

    def on_timer(self):
        self.private_executor.spin_once(timeout_sec=0.1)


class ChainedRequests(Node):
    """A done callback runs on the executor that spins the client's node."""

    def __init__(self):
        super().__init__('chained_requests')
        self.map_client = self.create_client(GetMap, 'map_server/map')
        self.create_timer(1.0, self.on_timer)

    def on_timer(self):
        self.map_client.call_async(GetMap.Request()).add_done_callback(self.on_first)

    def on_first(self, future):
        self.map_client.call(GetMap.Request())  # ROS101


def main():
    rclpy.init()
    executor = MultiThreadedExecutor()
    executor.add_node(ReentrantSync('reentrant_sync'))
    executor.spin_once()
    single = ReentrantSync('reentrant_single')
    rclpy.spin(LambdaSync())
    rclpy.spin(single)
    rclpy.spin(Relay())
    rclpy.spin(ChainedRequests())
