"""Reads the receiver's serial port and parses every sentence in place."""
import rclpy

from gnss_driver.driver import GnssDriver


def main(args=None):
    rclpy.init(args=args)
    driver = GnssDriver()
    port = driver.declare_parameter('port', '/dev/ttyUSB0').value
    with open(port, encoding='ascii') as serial:
        while rclpy.ok():
            driver.add_sentence(serial.readline().strip())
    rclpy.shutdown()
