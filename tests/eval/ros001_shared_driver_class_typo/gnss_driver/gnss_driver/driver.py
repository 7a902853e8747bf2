"""The driver class every front end runs: /fix, /vel and /time_reference are its interface.

The topic driver subscribes to 'nmea_sentences', a slip for the reader's 'nmea_sentence':
both ends are reported with the near name; the driver's own outputs stay quiet.
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
