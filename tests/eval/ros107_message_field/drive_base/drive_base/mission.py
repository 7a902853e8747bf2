"""Goals and detections of widely used message packages outside the core (nav2_msgs,
vision_msgs, control_msgs): their fields are known too."""
import rclpy
from control_msgs.msg import JointJog
from nav2_msgs.action import NavigateToPose
from rclpy.action import ActionClient
from rclpy.node import Node
from vision_msgs.msg import Detection2D, ObjectHypothesisWithPose


class Mission(Node):
    def __init__(self):
        super().__init__('mission')
        self.navigator = ActionClient(self, NavigateToPose, 'navigate_to_pose')
        self.jog = self.create_publisher(JointJog, 'servo/joint_jog', 10)
        self.detections = self.create_publisher(Detection2D, 'detections', 10)
        self.create_timer(1.0, self.tick)

    def tick(self):
        goal = NavigateToPose.Goal()
        goal.pose.header.frame_id = 'map'
        goal.pose.pose.position.x = 2.0
        goal.behaviour_tree = ''  # ROS107
        self.navigator.send_goal_async(goal)
        jog = JointJog()
        jog.joint_names = ['shoulder']
        jog.velocities = [0.1]
        jog.duration = 1  # ROS107
        self.jog.publish(jog)
        found = Detection2D()
        hypothesis = ObjectHypothesisWithPose()
        hypothesis.hypothesis.class_id = 'person'
        hypothesis.hypothesis.score = 0.9
        found.results.append(hypothesis)
        found.bbox.center.position.x = 320.0
        found.bbox.size_x = 40.0
        found.bbox.width = 40.0  # ROS107
        self.detections.publish(found)


def main():
    rclpy.init()
    rclpy.spin(Mission())
