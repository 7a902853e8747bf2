"""Publishes the battery state as a percentage and serves a calibration request."""
import rclpy
from example_interfaces.srv import AddTwoInts
from rclpy.node import Node
from std_msgs.msg import Float32


class Battery(Node):

    def __init__(self):
        super().__init__('battery')
        self.level_pub = self.create_publisher(Float32, 'battery/level', 10)
        self.create_service(AddTwoInts, 'battery/calibrate', self.on_calibrate)
        self.timer = self.create_timer(1.0, self.report)

    def on_calibrate(self, request, response):
        response.sum = request.a + request.b
        return response

    def report(self):
        msg = Float32()
        msg.data = 87.5
        self.level_pub.publish(msg)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Battery())
    rclpy.shutdown()
