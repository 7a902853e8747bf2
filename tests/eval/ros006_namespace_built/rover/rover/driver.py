"""The base driver, in the namespace its launch file gives it — or the root one."""
import rclpy
from geometry_msgs.msg import Twist
from rclpy.node import Node
from std_msgs.msg import String


class Driver(Node):

    def __init__(self):
        super().__init__('driver')
        self.create_subscription(Twist, self.get_namespace() + '/cmd_vel', self.on_cmd, 10)  # ROS006
        self.state_pub = self.create_publisher(String, 'state', 10)

    def on_cmd(self, msg):
        self.state_pub.publish(String(data='moving'))


class ArmDriver(Node):
    """Always in the arm's namespace, whoever starts it."""

    def __init__(self):
        super().__init__('arm_driver', namespace='arm')
        self.create_subscription(Twist, self.get_namespace() + '/cmd_vel', self.on_cmd, 10)

    def on_cmd(self, msg):
        self.get_logger().info('arm command')


def main(args=None):
    rclpy.init(args=args)
    executor = rclpy.executors.SingleThreadedExecutor()
    executor.add_node(Driver())
    executor.add_node(ArmDriver())
    executor.spin()
