import rclpy
from geometry_msgs.msg import Quaternion
from rclpy.node import Node
from visualization_msgs.msg import Marker


def goal_sphere(frame):
    marker = Marker()
    marker.header.frame_id = frame
    marker.type = Marker.SPHERE
    marker.color.a = 1.0
    marker.color.r = 1  # ROS107
    marker.pose.position.z = 0.0
    marker.pose.orientation = Quaternion(w=1.0)
    return marker


class DualMarkers(Node):

    def __init__(self):
        super().__init__('dual_markers')
        self.pub = self.create_publisher(Marker, 'goal_marker', 1)
        self.create_timer(0.5, lambda: self.pub.publish(goal_sphere('base_link')))


def main():
    rclpy.init()
    rclpy.spin(DualMarkers())
