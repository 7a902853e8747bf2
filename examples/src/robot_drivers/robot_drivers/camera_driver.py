"""A lifecycle camera driver: its publisher exists only once configured.

The image publisher is a lifecycle publisher created in ``on_configure``;
it only sends frames while the node is active.
"""
from typing import Optional

import rclpy
from rclpy.lifecycle import Node, Publisher, State, TransitionCallbackReturn
from rclpy.timer import Timer
from sensor_msgs.msg import Image


class CameraDriver(Node):
    """Publishes ``/image_raw`` between activate and deactivate."""

    FRAME_ID = 'camera'

    def __init__(self) -> None:
        super().__init__('camera_driver')
        self.declare_parameter('fps', 15.0)
        self._image_pub: Optional[Publisher] = None
        self._timer: Optional[Timer] = None

    def on_configure(self, state: State) -> TransitionCallbackReturn:
        self._image_pub = self.create_lifecycle_publisher(
            Image, 'image_raw', 10)
        fps = self.get_parameter('fps').value
        self._timer = self.create_timer(1.0 / fps, self.publish_frame)
        return TransitionCallbackReturn.SUCCESS

    def on_cleanup(self, state: State) -> TransitionCallbackReturn:
        self.destroy_timer(self._timer)
        self.destroy_publisher(self._image_pub)
        self._timer = None
        self._image_pub = None
        return TransitionCallbackReturn.SUCCESS

    def publish_frame(self) -> None:
        frame = Image()
        frame.header.stamp = self.get_clock().now().to_msg()
        frame.header.frame_id = self.FRAME_ID
        frame.encoding = 'rgb8'
        self._image_pub.publish(frame)


def main(args=None):
    rclpy.init(args=args)
    node = CameraDriver()
    try:
        rclpy.spin(node)
    finally:
        node.destroy_node()
        rclpy.shutdown()


if __name__ == '__main__':
    main()
