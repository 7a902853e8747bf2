import rclpy
from rclpy.node import Node
from std_msgs.msg import Bool


class StopRelay(Node):

    def __init__(self):
        super().__init__('stop_relay')
        topic = self.declare_parameter('input', 'obstacle_stop').value
        self.create_subscription(Bool, topic, self.on_stop, 10)
        self.motor_pub = self.create_publisher(Bool, '/motor/enable', 10)

    def on_stop(self, msg):
        self.motor_pub.publish(Bool(data=not msg.data))


def main():
    rclpy.init()
    rclpy.spin(StopRelay())
