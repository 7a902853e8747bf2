"""Parses raw sentences that another program (a sentence reader, a bag) publishes."""
from functools import partial

import rclpy
from nmea_msgs.msg import Sentence

from gnss_driver.driver import GnssDriver


def on_sentence(msg, driver):
    driver.add_sentence(msg.sentence, stamp=msg.header.stamp)


def main(args=None):
    rclpy.init(args=args)
    driver = GnssDriver()
    driver.create_subscription(Sentence, 'nmea_sentences', partial(on_sentence, driver=driver), 10)  # ROS003
    rclpy.spin(driver)
    rclpy.shutdown()
