"""A scripted teleop: enables the motors, then drives in a slow circle."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from std_srvs.srv import SetBool

from robot_base.names import CMD_VEL_TOPIC, ENABLE_MOTORS_SERVICE


class Teleop(Node):
    """Publishes velocity commands at a fixed rate.

    The motors are enabled through an asynchronous service call from the
    timer callback: a synchronous ``call()`` there would deadlock the
    single-threaded executor.
    """

    CMD_TOPIC = CMD_VEL_TOPIC
    LINEAR_SPEED = 0.2  # m/s
    ANGULAR_SPEED = 0.5  # rad/s

    def __init__(self) -> None:
        super().__init__('teleop')
        self._cmd_pub = self.create_publisher(Twist, self.CMD_TOPIC, 10)
        self._enable_client = self.create_client(
            SetBool, ENABLE_MOTORS_SERVICE)
        self._enable_future = None
        publish_period = 0.1  # seconds
        self.create_timer(publish_period, self.on_tick)

    def on_tick(self) -> None:
        if (self._enable_future is None
                and self._enable_client.service_is_ready()):
            request = SetBool.Request()
            request.data = True
            self._enable_future = self._enable_client.call_async(request)
        cmd = Twist()
        cmd.linear.x = self.LINEAR_SPEED
        cmd.angular.z = self.ANGULAR_SPEED
        self._cmd_pub.publish(cmd)


def main(args=None):
    rclpy.init(args=args)
    node = Teleop()
    try:
        rclpy.spin(node)
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
