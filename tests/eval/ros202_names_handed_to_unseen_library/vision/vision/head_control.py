"""Moves the head on behalf of a behaviour; the pose output is gated by the same library."""
import gated_io
from geometry_msgs.msg import PoseStamped


class HeadControl:
    def __init__(self, node, prefix):
        self.node = node
        self.pose_filter = gated_io.OnOffFilterState(self.node, 'pose/filter_state')
        self.pose = node.create_publisher(PoseStamped, prefix + '/set_head_pose', 1)
