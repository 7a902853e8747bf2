"""Reads the serial port and republishes the raw sentences for a topic driver to parse."""
import rclpy
from nmea_msgs.msg import Sentence
from rclpy.qos import qos_profile_sensor_data

from gnss_driver.driver import GnssDriver


def main(args=None):
    rclpy.init(args=args)
    driver = GnssDriver()
    sentence_pub = driver.create_publisher(Sentence, 'nmea_sentence', qos_profile_sensor_data)
    port = driver.declare_parameter('port', '/dev/ttyUSB0').value
    with open(port, encoding='ascii') as serial:
        while rclpy.ok():
            msg = Sentence()
            msg.sentence = serial.readline().strip()
            sentence_pub.publish(msg)
    rclpy.shutdown()
