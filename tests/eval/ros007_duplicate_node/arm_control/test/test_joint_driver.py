"""One fixture node per test function: each test is its own run, so the shared name is fine."""
import rclpy
from std_msgs.msg import Float64MultiArray


def test_driver_accepts_six_joints():
    rclpy.init()
    probe = rclpy.create_node('arm_test_probe')
    probe.create_publisher(Float64MultiArray, 'arm/joint_commands', 10)
    probe.destroy_node()
    rclpy.shutdown()


def test_driver_ignores_empty_commands():
    rclpy.init()
    probe = rclpy.create_node('arm_test_probe')
    probe.create_publisher(Float64MultiArray, 'arm/joint_commands', 10)
    probe.destroy_node()
    rclpy.shutdown()


def test_driver_declares_rate():
    rclpy.init()
    probe = rclpy.create_node('arm_test_probe')
    assert probe.get_name() == 'arm_test_probe'
    probe.destroy_node()
    rclpy.shutdown()
