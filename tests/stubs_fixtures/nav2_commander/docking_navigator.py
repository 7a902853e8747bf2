"""A navigator subclass that adds its own status publisher."""
import rclpy
from nav2_simple_commander.robot_navigator import BasicNavigator
from std_msgs.msg import String


class DockingNavigator(BasicNavigator):
    def __init__(self):
        super().__init__('docking_navigator')
        self.status_pub = self.create_publisher(String, 'dock_status', 10)


def main():
    rclpy.init()
    navigator = DockingNavigator()
    navigator.lifecycleStartup()
