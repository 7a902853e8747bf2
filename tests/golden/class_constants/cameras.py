"""Names from class constants, overridden in a subclass."""
import rclpy
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from sensor_msgs.msg import CameraInfo, Image


class CameraNode(Node):
    NODE_NAME = 'camera'
    IMAGE_TOPIC = 'image'
    INFO_TOPIC = 'camera_info'
    PUBLISH_PERIOD = 0.1

    def __init__(self):
        super().__init__(self.NODE_NAME)
        self.image_pub = self.create_publisher(Image, self.IMAGE_TOPIC, 10)
        self.info_pub = self.create_publisher(
            CameraInfo, CameraNode.INFO_TOPIC, 10)
        self.create_timer(self.PUBLISH_PERIOD, self.publish_frame)

    def publish_frame(self):
        self.image_pub.publish(Image())
        self.info_pub.publish(CameraInfo())


class DepthCameraNode(CameraNode):
    NODE_NAME = 'depth_camera'
    IMAGE_TOPIC = 'depth/image'
    PUBLISH_PERIOD = 0.2


def main(args=None):
    rclpy.init(args=args)
    executor = SingleThreadedExecutor()
    executor.add_node(CameraNode())
    executor.add_node(DepthCameraNode())
    executor.spin()
    rclpy.shutdown()


if __name__ == '__main__':
    main()
