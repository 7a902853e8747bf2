"""A second server whose namespace is absolute, so its node's namespace does not apply."""
import rclpy
from interactive_markers.interactive_marker_server import InteractiveMarkerServer


def main():
    rclpy.init()
    node = rclpy.create_node('planner_markers', namespace='arm')
    server = InteractiveMarkerServer(node, '/planner/markers')
    server.applyChanges()
    rclpy.spin(node)
