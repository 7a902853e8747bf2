"""The driver class every front end runs; a launch file starts only the serial driver.

The reader and the topic driver, which no launch file starts, run as written: the reader
publishes its raw sentences best effort, which the topic driver's reliable subscription
never receives.
"""
from geometry_msgs.msg import TwistStamped
from rclpy.node import Node
from sensor_msgs.msg import NavSatFix, TimeReference


class GnssDriver(Node):

    def __init__(self):
        super().__init__('gnss_driver')
        self.fix_pub = self.create_publisher(NavSatFix, 'fix', 10)
        self.vel_pub = self.create_publisher(TwistStamped, 'vel', 10)
        self.time_ref_pub = self.create_publisher(TimeReference, 'time_reference', 10)
        self.frame_id = self.declare_parameter('frame_id', 'gps').value

    def add_sentence(self, sentence, stamp=None):
        fix = NavSatFix()
        fix.header.frame_id = self.frame_id
        if sentence.startswith('$GPGGA'):
            self.fix_pub.publish(fix)
        elif sentence.startswith('$GPVTG'):
            self.vel_pub.publish(TwistStamped())
        else:
            self.time_ref_pub.publish(TimeReference())
