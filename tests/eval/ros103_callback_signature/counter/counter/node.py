from functools import partial

import rclpy
from rclpy.node import Node
from std_msgs.msg import Int32
from std_srvs.srv import SetBool, Trigger

from counter.handlers import ResetHandlers, log_reset, on_topic


class Counter(ResetHandlers, Node):
    def __init__(self):
        super().__init__('counter')
        self.count = 0
        self.create_service(SetBool, 'reset', self.on_reset)
        self.create_service(SetBool, 'reset_checked', self.on_reset_checked)
        self.create_service(SetBool, 'reset_delegated', self.on_reset_delegated)
        self.create_service(Trigger, 'ping', lambda request, response: response)
        self.create_timer(1.0, self.on_tick)  # ROS103
        self.create_timer(1.0, self.on_tick_with_default)
        self.create_timer(2.0, self.on_anything)
        self.create_subscription(Int32, 'count', self.on_message, 10)
        self.create_subscription(Int32, 'count_all', self.on_anything, 10)
        self.create_subscription(Int32, 'reset_request', log_reset, 10)  # ROS103
        self.create_subscription(Int32, 'tick', lambda: self.on_tick(None), 10)  # ROS103
        self.create_subscription(Int32, 'other', partial(on_topic, self, 'other'), 10)
        self.client = self.create_client(Trigger, 'ping')
        self.client.call_async(Trigger.Request()).add_done_callback(self.log_result)


def main():
    rclpy.init()
    rclpy.spin(Counter())
