"""Time stamps of whatever the recorder receives: stamped messages carry one, others do not."""
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import Imu
from std_msgs.msg import String


def stamp_of(msg, clock):
    if not hasattr(msg, 'header'):
        return clock.now().to_msg()
    return msg.header.stamp  # only messages with a header get here


def frame_of(msg):
    return msg.heder.frame_id  # ROS107


class Recorder(Node):

    def __init__(self):
        super().__init__('recorder')
        self.create_timer(1.0, self.on_tick)

    def on_tick(self):
        note = String(data='note')  # a message without a header: stamp_of stamps it with the clock
        self.get_logger().info(f'{stamp_of(note, self.get_clock())}')
        self.get_logger().info(frame_of(Imu()))


def main():
    rclpy.init()
    rclpy.spin(Recorder())
