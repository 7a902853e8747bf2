from rclpy.node import Node

DEFAULT_PORT = '/dev/ttyUSB0'


class SerialNode(Node):
    """Every serial node declares its port settings here."""

    def __init__(self, name, **kwargs):
        super().__init__(name, **kwargs)
        self.declare_parameter('port', DEFAULT_PORT)
        self.declare_parameter('baudrate', 4800)
        self.declare_parameter('frame_id', 'gps')

    def declare_timeouts(self):
        self.declare_parameter('timeout', 1.0)
