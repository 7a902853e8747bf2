"""Starts the server and sends it a mission (the server's node is the framework's, made in mission_core)."""
import rclpy
from example_interfaces.action import Fibonacci
from rclpy.action import ActionClient


def test_mission_is_served():
    rclpy.init()
    node = rclpy.create_node('mission_probe')
    client = ActionClient(node, Fibonacci, 'run_mission')
    assert client.wait_for_server(timeout_sec=10.0)
    node.destroy_node()


def test_mission_typo_is_not_served():
    rclpy.init()
    node = rclpy.create_node('mission_probe_typo')
    client = ActionClient(node, Fibonacci, 'run_misison')  # ROS009
    assert client.wait_for_server(timeout_sec=1.0)
    node.destroy_node()
