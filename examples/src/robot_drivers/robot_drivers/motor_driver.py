"""The motor driver: follows velocity commands once motors are enabled."""
import rclpy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry
from std_msgs.msg import String
from std_srvs.srv import SetBool

from robot_base.helpers import create_status_publisher
from robot_base.managed_node import ManagedNode
from robot_base.names import (CMD_VEL_TOPIC, ENABLE_MOTORS_SERVICE,
                              ODOM_TOPIC)


class MotorDriver(ManagedNode):
    """Subscribes to the command topic named by its ``cmd_topic`` parameter.

    Serves ``enable_motors``, publishes odometry and a private status topic.
    """

    def __init__(self) -> None:
        super().__init__('motor_driver')
        self.declare_parameter('cmd_topic', CMD_VEL_TOPIC)
        cmd_topic = self.get_parameter(
            'cmd_topic').get_parameter_value().string_value
        self._enabled = False
        self.create_subscription(Twist, cmd_topic, self.on_cmd_vel, 10)
        self.create_service(SetBool, ENABLE_MOTORS_SERVICE, self.on_enable)
        self._odom_pub = self.create_publisher(Odometry, ODOM_TOPIC, 10)
        self._status_pub = create_status_publisher(self)

    def on_cmd_vel(self, msg: Twist) -> None:
        if not self._enabled:
            return
        odom = Odometry()
        odom.header.stamp = self.get_clock().now().to_msg()
        odom.twist.twist = msg
        self._odom_pub.publish(odom)

    def on_enable(self, request: SetBool.Request,
                  response: SetBool.Response) -> SetBool.Response:
        self._enabled = request.data
        response.success = True
        response.message = 'enabled' if request.data else 'disabled'
        status = String()
        status.data = f'motors {response.message}'
        self._status_pub.publish(status)
        return response


def main(args=None):
    rclpy.init(args=args)
    node = MotorDriver()
    try:
        rclpy.spin(node)
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
