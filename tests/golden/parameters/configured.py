"""Parameters declared one at a time and in bulk, with and without defaults."""
import rclpy
from rclpy.node import Node
from rclpy.parameter import Parameter


class Configured(Node):

    def __init__(self):
        super().__init__('configured')
        self.declare_parameter('rate', 10.0)
        self.declare_parameter('frame_id', 'base_link')
        self.declare_parameter('retries', 3)
        self.declare_parameter('robot_name', Parameter.Type.STRING)
        self.declare_parameters(
            namespace='',
            parameters=[
                ('max_speed', 1.5),
                ('wheel_names', ['left', 'right']),
                ('use_imu', True),
            ])
        self.declare_parameters('limits', [('lower', -1.0), ('upper', 1.0)])
        self.rate = self.get_parameter('rate').value


def main(args=None):
    rclpy.init(args=args)
    node = Configured()
    rclpy.spin(node)
    node.destroy_node()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
