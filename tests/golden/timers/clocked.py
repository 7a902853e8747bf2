"""Timer periods from literals, variables, constants and arithmetic."""
import rclpy
from rclpy.node import Node

TICK_PERIOD = 0.25


class Clocked(Node):
    FAST_PERIOD = 0.01

    def __init__(self):
        super().__init__('clocked')
        period = 0.5
        self.create_timer(period, self.on_slow)
        self.create_timer(self.FAST_PERIOD, self.on_fast)
        self.create_timer(TICK_PERIOD, self.on_tick)
        frequency_hz = 4
        self.create_timer(1.0 / frequency_hz, self.on_tick)
        self.create_timer(timer_period_sec=2.0, callback=self.on_slow)

    def on_slow(self):
        self.get_logger().info('slow')

    def on_fast(self):
        pass

    def on_tick(self):
        self.get_logger().debug('tick')


def main(args=None):
    rclpy.init(args=args)
    node = Clocked()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
