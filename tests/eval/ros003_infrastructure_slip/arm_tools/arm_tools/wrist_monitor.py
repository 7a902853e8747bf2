"""Near-identical ends that must stay quiet: the right name, the name in a robot's namespace
(multi-robot systems), and a topic that only sounds like one (another type)."""
import rclpy
from rclpy.node import Node
from sensor_msgs.msg import JointState
from std_msgs.msg import String


class WristMonitor(Node):

    def __init__(self):
        super().__init__('wrist_monitor')
        self.create_subscription(JointState, 'joint_states', self.on_joints, 10)
        self.create_subscription(JointState, '/arm1/joint_states', self.on_joints, 10)
        self.create_subscription(String, 'clocks', self.on_note, 10)

    def on_joints(self, msg):
        self.get_logger().debug(f'{len(msg.name)} joints')

    def on_note(self, msg):
        self.get_logger().info(msg.data)


def main():
    rclpy.init()
    rclpy.spin(WristMonitor())
