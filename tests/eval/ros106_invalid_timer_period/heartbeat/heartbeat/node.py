import sys

import rclpy
from rclpy.node import Node
from std_msgs.msg import Header

from heartbeat.rates import period_of


class Heartbeat(Node):
    def __init__(self, mode):
        super().__init__('heartbeat')
        self.pub = self.create_publisher(Header, 'heartbeat', 10)
        self.create_timer(period_of(mode), self.beat)  # ROS106
        self.create_timer('0.5', self.beat)
        self.create_timer('half a second', self.beat)  # ROS106
        self.create_timer(-1, self.beat)  # ROS106
        self.declare_parameter('watchdog_period', 0.0)
        watchdog = self.get_parameter('watchdog_period').value
        self.create_timer(watchdog, self.check)
        self.loop_rate = self.create_rate(0)  # ROS106
        self.slow_rate = self.create_rate(period_of('slow'))

    def beat(self):
        self.pub.publish(Header())

    def check(self):
        pass


def main():
    rclpy.init()
    rclpy.spin(Heartbeat(sys.argv[1] if len(sys.argv) > 1 else 'max'))


class Watchdog(Node):
    """A period that may be 0, guarded by a test: the timer is only created when it is positive."""

    def __init__(self, enabled):
        super().__init__('watchdog')
        period = 0.5 if enabled else 0.0
        if period > 0:
            self.create_timer(period, self.check)
        if enabled:
            self.create_timer(0, self.check)  # ROS106

    def check(self):
        pass


class Starter(Node):
    """Period 0 as a one-shot: the callback cancels its own timer, so it runs once when the
    executor starts spinning. Cancelling another timer does not make a timer one-shot."""

    def __init__(self):
        super().__init__('starter')
        self.start_timer = self.create_timer(0.0, self.start)
        self.poll_timer = self.create_timer(0, self.poll)  # ROS106
        self.watch_timer = self.create_timer(1.0, self.watch)

    def start(self):
        self.start_timer.cancel()
        self.get_logger().info('started')

    def poll(self):
        self.destroy_timer(self.watch_timer)

    def watch(self):
        pass
