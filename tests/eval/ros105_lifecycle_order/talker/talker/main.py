import sys

import rclpy

from talker.node import Talker, make_talker


def main():
    node = make_talker('early')  # ROS105
    rclpy.init(args=sys.argv)
    rclpy.spin(node)
    rclpy.shutdown()


def restart():
    rclpy.init()
    node = Talker()
    rclpy.spin_once(node, timeout_sec=1.0)
    node.destroy_node()
    node.add_heartbeat()  # ROS105
    rclpy.shutdown()
    late = Talker('late')  # ROS105
    rclpy.spin_once(late)


def ordered():
    """The correct twin: init, create, destroy, shut down, and a second life after a re-init."""
    rclpy.init()
    node = Talker()
    if len(sys.argv) > 1:
        node.destroy_node()
    node.add_heartbeat()
    rclpy.spin_once(node)
    node.destroy_node()
    rclpy.shutdown()
    rclpy.init()
    again = Talker('again')
    again.destroy_node()
    rclpy.try_shutdown()


def reconnect():
    """The same helper makes the node anew after the first one was destroyed: each life is in
    order (the twin of ``handover``)."""
    rclpy.init()
    node = make_talker('probe')
    rclpy.spin_once(node, timeout_sec=1.0)
    node.destroy_node()
    node = make_talker('probe')
    node.add_heartbeat()
    rclpy.spin_once(node)
    node.destroy_node()
    rclpy.shutdown()


def handover():
    """Another node made after the destroy does not bring the first one back."""
    rclpy.init()
    node = Talker()
    node.destroy_node()
    spare = make_talker('spare')
    node.add_heartbeat()  # ROS105
    rclpy.spin(spare)
    rclpy.shutdown()
