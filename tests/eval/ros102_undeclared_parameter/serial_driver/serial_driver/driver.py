import rclpy
from rclpy.parameter import Parameter

from serial_driver.base import SerialNode


class Driver(SerialNode):
    def __init__(self):
        super().__init__('gps_driver')
        self.port = self.get_parameter('port').value
        self.frame = self.get_parameter('frame_id').value
        self.rate = self.get_parameter('rate').value  # ROS102
        self.use_sim = self.get_parameter('use_sim_time').value
        self.timeout = self.get_parameter_or('timout', 1.0)  # ROS102
        self.declare_timeouts()
        self.declare_timeouts()  # ROS102
        self.create_timer(1.0, self.on_timer)

    def on_timer(self):
        baud, frame = self.get_parameters(['baudrate', 'frame_id'])
        self.set_parameters([Parameter('frame', Parameter.Type.STRING, 'gps_link')])  # ROS102
        self.set_parameters([Parameter('frame_id', Parameter.Type.STRING, 'gps_link')])


class RetryingDriver(SerialNode):
    """A repeated declaration inside try/except or behind a check is deliberate."""

    def __init__(self):
        super().__init__('retrying_driver')
        try:
            self.declare_parameter('frame_id', 'gps')
        except Exception:
            pass
        if not self.has_parameter('baudrate'):
            self.declare_parameter('baudrate', 4800)


def main():
    rclpy.init()
    rclpy.spin(Driver())
    rclpy.spin(RetryingDriver())
