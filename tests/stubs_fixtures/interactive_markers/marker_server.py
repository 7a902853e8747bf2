"""Offers one draggable marker with a context menu to rviz."""
import rclpy
from interactive_markers import InteractiveMarkerServer, MenuHandler
from rclpy.node import Node
from std_msgs.msg import String
from visualization_msgs.msg import InteractiveMarker


class MarkerServer(Node):
    def __init__(self):
        super().__init__('marker_server', namespace='ui')
        self.server = InteractiveMarkerServer(self, 'simple_marker')
        self.menu = MenuHandler()
        self.menu.insert('Reset', callback=self.on_reset)
        marker = InteractiveMarker()
        marker.name = 'goal'
        self.server.insert(marker, feedback_callback=self.on_feedback)
        self.menu.apply(self.server, marker.name)
        self.server.applyChanges()

    def on_feedback(self, feedback):
        self.goal_pub = self.create_publisher(String, 'marker_goal', 10)

    def on_reset(self, feedback):
        self.reset_pub = self.create_publisher(String, 'marker_reset', 10)


def main():
    rclpy.init()
    rclpy.spin(MarkerServer())
