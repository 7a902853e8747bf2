"""An arm driver written against the company's wrapper library."""
import rclpy
from acme_robot import RobotBase
from acme_robot.util import make_pub, on_command
from sensor_msgs.msg import JointState


class ArmDriver(RobotBase):
    def __init__(self):
        super().__init__('arm_driver', namespace='arm')
        self.joint_pub = make_pub(self, 'joint_states', JointState)
        on_command(self, 'gripper', self.on_gripper)

    def on_gripper(self, msg):
        self.joint_pub.publish(JointState())


def main():
    rclpy.init()
    rclpy.spin(ArmDriver())
