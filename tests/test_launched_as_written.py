"""What launch files say, and what they do not: programs they start apart still meet when they
run as written (``ros2 run``), and a remap onto a name is not a claim on the names under it.

The rules judge the system as the workspace's launch files start it; the pair rules (ROS005,
ROS007) also judge the nodes under the names their code gives them, and the absence rules take
the names a launched node's code writes as near names for a node no launch file starts (that
node runs as written, beside the launched executables run as written). Each case has a
near-identical twin without the bug, which must stay quiet.
"""
from __future__ import annotations

from pathlib import Path

from test_precision_on_survey6_repos import ament_python, sites
from test_recall_mechanisms import findings
from test_workspace_discovery import write

# -- a voice robot: a microphone and a speech node launched in the robot's namespace, a speech
# -- recogniser run on its own (``ros2 run``) -----------------------------------------------------
MICROPHONE = """
    import rclpy
    from rclpy.node import Node
    from rclpy.qos import qos_profile_sensor_data

    from voice_msgs.msg import AudioFrame


    class Microphone(Node):
        def __init__(self):
            super().__init__('microphone')
            self.frames = self.create_publisher(AudioFrame, 'audio_frames', qos_profile_sensor_data)
            self.create_timer(0.02, self.capture)

        def capture(self):
            self.frames.publish(AudioFrame())


    def main():
        rclpy.init()
        rclpy.spin(Microphone())
"""

SPEECH = """
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import Bool, String


    class Speech(Node):
        def __init__(self):
            super().__init__('{name}')
            self.speaking = self.create_publisher(Bool, 'speaking', 10)
            self.create_subscription(String, 'say', self.say, 10)

        def say(self, msg):
            self.speaking.publish(Bool(data=True))


    def main():
        rclpy.init()
        rclpy.spin(Speech())
"""

RECOGNISER = """
    import rclpy
    from rclpy.node import Node
    from rclpy.qos import QoSProfile, qos_profile_sensor_data
    from std_msgs.msg import Bool, String

    from voice_msgs.msg import AudioFrame

    FRAMES_QOS = {frames_qos}


    class Recogniser(Node):
        def __init__(self):
            super().__init__('recogniser')
            self.muted = False
            self.create_subscription(AudioFrame, 'audio_frames', self.on_frame, FRAMES_QOS)
            self.create_subscription(Bool, '{speaking}', self.on_speaking, 10)
            self.text = self.create_publisher(String, 'say', 10)

        def on_speaking(self, msg):
            self.muted = msg.data

        def on_frame(self, frame):
            if not self.muted:
                self.text.publish(String(data='heard'))


    def main():
        rclpy.init()
        rclpy.spin(Recogniser())
"""

BRINGUP = """
    from launch import LaunchDescription
    from launch_ros.actions import Node


    def generate_launch_description():
        return LaunchDescription([
            Node(package='voice_mic', executable='microphone', namespace='robot'),
            Node(package='voice_tts', executable='speech', namespace='robot', name='tts'),
        ])
"""

AUDIO_FRAME = "uint8[] data\n"


def voice_workspace(root: Path, speech_name: str = "tts_node", frames_qos: str = "qos_profile_sensor_data",
                    speaking: str = "speaking") -> Path:
    return write(root, {
        **ament_python("voice_mic", "'microphone = voice_mic.microphone:main'"),
        "voice_mic/voice_mic/microphone.py": MICROPHONE,
        **ament_python("voice_tts", "'speech = voice_tts.speech:main'"),
        "voice_tts/voice_tts/speech.py": SPEECH.format(name=speech_name),
        **ament_python("voice_asr", "'recogniser = voice_asr.recogniser:main'"),
        "voice_asr/voice_asr/recogniser.py": RECOGNISER.format(frames_qos=frames_qos, speaking=speaking),
        **ament_python("voice_bringup"),
        "voice_bringup/launch/robot.launch.py": BRINGUP,
        "voice_msgs/msg/AudioFrame.msg": AUDIO_FRAME,
    })


def test_a_node_name_copied_from_a_program_it_talks_to_is_reported_as_written(tmp_path: Path) -> None:
    """The speech node's code took the recogniser's name: the launch file starts it as
    ``/robot/tts``, but ``ros2 run`` of both programs starts two ``/recogniser`` that talk."""
    root = voice_workspace(tmp_path, speech_name="recogniser")
    reported = findings(root, ["ROS007"])
    assert sites(reported) == [("ROS007", "voice_asr/voice_asr/recogniser.py", 13),
                               ("ROS007", "voice_tts/voice_tts/speech.py", 8)]
    assert reported[0][3] == (
        "node '/recogniser' is also created at voice_tts/voice_tts/speech.py:8, and they run together "
        "(they talk over topic '/speaking') when started as written in code (`ros2 run`), without the "
        "launch files that rename them")


def test_distinct_names_in_code_are_quiet(tmp_path: Path) -> None:
    """The twin: the speech node's code has its own name."""
    assert findings(voice_workspace(tmp_path), ["ROS007"]) == []


def test_a_name_shared_by_programs_that_do_not_talk_is_quiet_as_written(tmp_path: Path) -> None:
    """Two programs of one name that share no topic are alternatives (``ros2 run`` one or the
    other), as they are when neither is launched."""
    root = voice_workspace(tmp_path, speech_name="microphone")
    assert findings(root, ["ROS007"]) == []


def test_a_subscription_its_publisher_cannot_serve_is_reported_as_written(tmp_path: Path) -> None:
    """The recogniser asks for reliable frames of the best-effort microphone: launched, the
    microphone publishes ``/robot/audio_frames``; run as written both use ``/audio_frames``."""
    root = voice_workspace(tmp_path, frames_qos="QoSProfile(depth=10)")
    reported = findings(root, ["ROS005"])
    assert sites(reported) == [("ROS005", "voice_asr/voice_asr/recogniser.py", 15)]
    assert reported[0][3].endswith(
        "best-effort publisher, reliable subscription (when both run as written in code, `ros2 run`, "
        "without the launch files that start them apart)")


def test_a_matching_profile_is_quiet_as_written(tmp_path: Path) -> None:
    """The twin: the recogniser subscribes with the sensor-data profile."""
    assert findings(voice_workspace(tmp_path), ["ROS005"]) == []


def test_a_misspelt_name_of_a_launched_program_is_named_as_it_is_written(tmp_path: Path) -> None:
    """The recogniser, run as written, misspells the speech node's ``speaking``: launched, the
    speech node publishes ``/robot/speaking``, which is no near name of ``/speakng``; its code
    writes ``speaking``, which the recogniser meets when both run as written."""
    root = voice_workspace(tmp_path, speaking="speakng")
    reported = findings(root, ["ROS003"])
    assert sites(reported) == [("ROS003", "voice_asr/voice_asr/recogniser.py", 16)]
    assert reported[0][3] == ("topic '/speakng' has no publisher; did you mean '/speaking' "
                              "(published at voice_tts/voice_tts/speech.py:9)?")


def test_the_name_a_launched_program_writes_is_quiet(tmp_path: Path) -> None:
    """The twin: spelt right, the recogniser's subscription meets the speech node's code."""
    assert findings(voice_workspace(tmp_path), ["ROS003"]) == []


# -- a name under the one a launch file remaps an installed program onto is not that program's ----
BASE_DRIVER = """
    import rclpy
    from geometry_msgs.msg import Twist
    from nav_msgs.msg import Odometry
    from rclpy.node import Node


    class BaseDriver(Node):
        def __init__(self):
            super().__init__('base_driver')
            self.odom = self.create_publisher(Odometry, 'odom/wheels', 10)
            self.create_subscription(Twist, 'cmd_vel', self.drive, 10)

        def drive(self, msg):
            self.odom.publish(Odometry())


    def main():
        rclpy.init()
        rclpy.spin(BaseDriver())
"""

MONITOR = """
    import rclpy
    from geometry_msgs.msg import Twist
    from nav_msgs.msg import Odometry
    from rclpy.node import Node
    from sensor_msgs.msg import CompressedImage


    class Monitor(Node):
        def __init__(self):
            super().__init__('monitor')
            self.create_subscription(Odometry, '{wheels}', self.on_wheels, 10)
            self.create_subscription(Odometry, '/odom', self.on_fused, 10)
            self.create_subscription(CompressedImage, '/front_camera/image_raw/compressed', self.on_image, 10)
            self.cmd = self.create_publisher(Twist, 'cmd_vel', 10)

        def on_wheels(self, msg):
            self.cmd.publish(Twist())

        def on_fused(self, msg):
            pass

        def on_image(self, msg):
            pass


    def main():
        rclpy.init()
        rclpy.spin(Monitor())
"""

ROVER_LAUNCH = """
    from launch import LaunchDescription
    from launch_ros.actions import Node


    def generate_launch_description():
        return LaunchDescription([
            Node(package='rover_base', executable='base_driver'),
            Node(package='rover_base', executable='monitor'),
            Node(package='robot_localization', executable='ekf_node',
                 remappings=[('odometry/filtered', '/odom')]),
            Node(package='usb_cam', executable='usb_cam_node_exe',
                 remappings=[('image_raw', '/front_camera/image_raw')]),
        ])
"""


def rover_workspace(root: Path, wheels: str) -> Path:
    return write(root, {
        **ament_python("rover_base", "'base_driver = rover_base.base_driver:main', "
                                     "'monitor = rover_base.monitor:main'"),
        "rover_base/rover_base/base_driver.py": BASE_DRIVER,
        "rover_base/rover_base/monitor.py": MONITOR.format(wheels=wheels),
        "rover_base/launch/rover.launch.py": ROVER_LAUNCH,
    })


def test_a_misspelt_name_under_a_remap_target_of_an_installed_program_is_reported(tmp_path: Path) -> None:
    """The launch file remaps the installed EKF's output onto ``/odom``: that program uses
    ``/odom``, not ``/odom/wheel``, which misspells the driver's ``/odom/wheels``."""
    reported = findings(rover_workspace(tmp_path, "/odom/wheel"), ["ROS003"])
    assert sites(reported) == [("ROS003", "rover_base/rover_base/monitor.py", 11)]
    assert "did you mean '/odom/wheels'" in reported[0][3]


def test_the_remap_target_and_its_transport_topics_are_the_installed_programs(tmp_path: Path) -> None:
    """The twin: spelt right; ``/odom`` is the EKF's, and the compressed image one token under
    the camera's remapped ``/front_camera/image_raw`` is its image_transport topic."""
    assert findings(rover_workspace(tmp_path, "/odom/wheels"), ["ROS003"]) == []
