"""ROS006 on the name a launched node has when it runs as written: a speech node's status topic
comes from a parameter whose launch file sets a valid name, but a space slipped into the
default in code. Started with ``ros2 run`` (no launch file), rclpy raises. The twin with a
valid default is quiet, and so is an empty default that disables the end."""
from __future__ import annotations

from pathlib import Path

from test_recall_globals_and_escapes import package
from test_workspace_discovery import write

from flake8_rosgraph.cache import build_report
from flake8_rosgraph.options import Settings

SPEECH = """
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import String


    class SpeechInput(Node):
        def __init__(self):
            super().__init__('speech_input')
            status = self.declare_parameter('status_topic', '/agent/speech_input_status').value
            self.status = self.create_publisher(String, status, 10)
            debug = self.declare_parameter('debug_topic', '').value
            if debug:
                self.debug = self.create_publisher(String, debug, 10)


    def main():
        rclpy.init()
        rclpy.spin(SpeechInput())
"""
LISTENER = """
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import String


    def main():
        rclpy.init()
        node = Node('agent')
        node.create_subscription(String, '/agent/speech_input_status', print, 10)
        rclpy.spin(node)
"""
LAUNCH = """
    import os

    from ament_index_python.packages import get_package_share_directory
    from launch import LaunchDescription
    from launch_ros.actions import Node


    def generate_launch_description():
        params = os.path.join(get_package_share_directory('voice'), 'config', 'agent.yaml')
        return LaunchDescription([
            Node(package='voice', executable='speech', parameters=[params]),
            Node(package='voice', executable='agent'),
        ])
"""
PARAMS = """
    speech_input:
      ros__parameters:
        status_topic: /agent/speech_input_status
"""


def _invalid(tmp_path: Path, default: str) -> list[tuple[int, str]]:
    files = package("voice", "'speech = voice.speech:main', 'agent = voice.agent:main'",
                    {"speech": SPEECH.replace("'/agent/speech_input_status'", repr(default)),
                     "agent": LISTENER})
    files["voice/launch/agent.launch.py"] = LAUNCH
    files["voice/config/agent.yaml"] = PARAMS
    report = build_report(write(tmp_path, files), Settings())
    return [(f.location.line, f.message) for f in report.findings if f.code == "ROS006"]


def test_an_invalid_default_the_launch_file_replaces_is_reported_as_written(tmp_path: Path) -> None:
    (finding,) = _invalid(tmp_path, "/agent/speech_in put_status")
    assert finding[0] == 10 and "when the node runs as written" in finding[1]


def test_a_valid_default_is_quiet(tmp_path: Path) -> None:
    assert _invalid(tmp_path, "/agent/speech_input_status") == []


CAMERA = """
    import rclpy
    from rclpy.node import Node
    from sensor_msgs.msg import CompressedImage, Image


    class ImageProcess(Node):
        '''Each output is off while its topic parameter is empty.'''

        def __init__(self):
            super().__init__('image_process')
            self.output_topic = self.declare_parameter('output_topic', '').value
            self.compressed_topic = self.declare_parameter('compressed_topic', '').value
            self.enable_raw = self.declare_parameter('enable_raw', True).value
            self.enable_compressed = self.declare_parameter('enable_compressed', True).value
            self.resized_topic = self.declare_parameter('resized_topic', '').value
            self.resized_compressed_topic = self.declare_parameter('resized_compressed_topic', '').value
            if self.enable_raw:
                self.raw_pub = self.create_publisher(Image, self.output_topic, 10)
                self.resized_pub = self.create_publisher(Image, self.resized_topic, 10)
            if self.enable_compressed:
                self.compressed_pub = self.create_publisher(CompressedImage, self.compressed_topic, 10)
                self.resized_compressed_pub = self.create_publisher(
                    CompressedImage, self.resized_compressed_topic, 10)


    def main():
        rclpy.init()
        rclpy.spin(ImageProcess())
"""


def test_outputs_left_empty_make_no_type_mismatch(tmp_path: Path) -> None:
    """Two outputs of different types, both on their empty default: rcl rejects the empty
    name, so neither end exists, and there is no type mismatch between them (ROS004)."""
    files = package("camera", "'process = camera.process:main'", {"process": CAMERA})
    report = build_report(write(tmp_path, files), Settings())
    assert [f.code for f in report.findings if f.code in ("ROS004", "ROS006")] == []
