"""Publishes camera frames and listens for the detections."""
import rclpy
from geometry_msgs.msg import PoseStamped
from rclpy.node import Node
from sensor_msgs.msg import Image
from std_msgs.msg import String


class Camera(Node):
    def __init__(self):
        super().__init__('camera')
        self.frames = self.create_publisher(Image, '/camera/image_raw', 1)
        self.mode = self.create_publisher(String, 'mode', 1)
        self.create_subscription(String, 'detections', self.on_detections, 10)
        self.create_subscription(PoseStamped, '/detector/set_head_pose', self.on_head_pose, 1)
        self.create_timer(0.1, self.tick)

    def tick(self):
        self.frames.publish(Image(width=640, height=480))

    def on_head_pose(self, msg):
        self.get_logger().debug(msg.header.frame_id)

    def on_detections(self, msg):
        self.get_logger().info(msg.data)


def main(args=None):
    rclpy.init(args=args)
    rclpy.spin(Camera())
