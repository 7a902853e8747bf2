"""Entities that exist only on some paths through __init__."""
import os

import rclpy
from rclpy.node import Node
from std_msgs.msg import String
from std_srvs.srv import Trigger


class Recorder(Node):

    def __init__(self):
        super().__init__('recorder')
        self.events = []
        self.create_subscription(String, 'events', self.on_event, 10)
        if 'RECORDER_DEBUG' in os.environ:
            self.debug_pub = self.create_publisher(
                String, 'recorder_debug', 10)
        if os.environ.get('RECORDER_MODE') == 'service':
            self.create_service(Trigger, 'dump', self.on_dump)
        else:
            self.create_timer(10.0, self.on_dump_timer)

    def on_event(self, msg):
        self.events.append(msg.data)

    def on_dump(self, request, response):
        response.success = True
        response.message = '\n'.join(self.events)
        return response

    def on_dump_timer(self):
        self.get_logger().info('%d events' % len(self.events))


def main(args=None):
    rclpy.init(args=args)
    node = Recorder()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
