"""Drives a robot between two poses with Nav2's simple commander."""
import rclpy
from geometry_msgs.msg import PoseStamped
from nav2_simple_commander.robot_navigator import BasicNavigator, TaskResult


def main():
    rclpy.init()
    navigator = BasicNavigator(namespace='robot1')
    navigator.waitUntilNav2Active()
    goal = PoseStamped()
    goal.header.frame_id = 'map'
    navigator.goToPose(goal)
    while not navigator.isTaskComplete():
        navigator.getFeedback()
    if navigator.getResult() == TaskResult.SUCCEEDED:
        navigator.info('arrived')
