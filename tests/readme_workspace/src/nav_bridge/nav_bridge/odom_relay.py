import rclpy
from nav_msgs.msg import Odometry
from rclpy.node import Node
from std_srvs.srv import Trigger


class OdomRelay(Node):
    def __init__(self):
        super().__init__('odom_relay')
        self.create_subscription(Odometry, 'odmo', self.on_odom, 10)
        self.reset = self.create_client(Trigger, 'reset_odometry')
        self.create_timer(1.0, self.on_timer)
        self.last = None

    def on_odom(self, msg):
        self.last = msg

    def on_timer(self):
        if self.last is None:
            return
        if abs(self.last.pose.pose.position.x) > 100.0:
            self.get_logger().warn('odometry drifted: resetting')
            self.reset.call(Trigger.Request())


def main():
    rclpy.init()
    rclpy.spin(OdomRelay())
