"""A GPS driver: /fix and /vel are its interface, consumed outside this workspace. No findings."""
import rclpy
from geometry_msgs.msg import TwistStamped
from rclpy.node import Node
from sensor_msgs.msg import NavSatFix
from std_srvs.srv import Trigger


class GpsDriver(Node):

    def __init__(self):
        super().__init__('gps_driver')
        self.fix_pub = self.create_publisher(NavSatFix, 'fix', 10)
        self.vel_pub = self.create_publisher(TwistStamped, 'vel', 10)
        self.create_subscription(NavSatFix, 'rtk_corrections', self.on_corrections, 10)
        self.create_service(Trigger, 'reset', self.on_reset)
        self.timer = self.create_timer(0.2, self.poll)

    def on_corrections(self, msg):
        self.get_logger().debug('correction received')

    def on_reset(self, request, response):
        response.success = True
        return response

    def poll(self):
        self.fix_pub.publish(NavSatFix())
        self.vel_pub.publish(TwistStamped())


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(GpsDriver())
    rclpy.shutdown()
