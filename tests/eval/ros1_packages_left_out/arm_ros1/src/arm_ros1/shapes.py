from geometry_msgs.msg import Quaternion
from visualization_msgs.msg import Marker


def goal_sphere(frame):
    marker = Marker()
    marker.header.frame_id = frame
    marker.type = Marker.SPHERE
    marker.color.a = 1
    marker.color.r = 1
    marker.pose.position.z = 0
    marker.pose.orientation = Quaternion(0, 0, 0, 1)
    return marker
