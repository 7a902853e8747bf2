"""A state channel several nodes share: each stage of a voice pipeline announces its state on
``/pipeline_state`` and listens there for the other stages' states. Each stage publishes and
subscribes the topic on purpose, so none of them is a self-loop (ROS002), and two alternative
programs of one stage (a local and a cloud speech input, given one node name) that hear each
other only on that channel are not shown to run together (ROS007).

Twins: a node that subscribes to its own output when no other node publishes and listens on the
topic is a loop; a stage listening on the channel with another message type is a loop; two
stages of one name that also talk over an ordinary topic run together."""
from __future__ import annotations

from pathlib import Path

from test_recall_globals_and_escapes import package
from test_workspace_discovery import write

from flake8_rosgraph.cache import build_report
from flake8_rosgraph.options import Settings

STATE = """
    from std_msgs.msg import String

    STATE_TOPIC = '/pipeline_state'


    class StateMixin:
        '''Every stage announces what it is doing and follows what the others do.'''

        def setup_state(self):
            self.state_pub = self.create_publisher(String, STATE_TOPIC, 10)
            self.create_subscription(String, STATE_TOPIC, self.on_state, 10)

        def announce(self, state):
            self.state_pub.publish(String(data=state))

        def on_state(self, msg):
            self.get_logger().info(f'state: {msg.data}')
"""
SPEECH_LOCAL = """
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import String

    from voice.state import StateMixin


    class SpeechInput(StateMixin, Node):
        '''Speech to text on this computer.'''

        def __init__(self):
            super().__init__('speech_input')
            self.setup_state()
            self.text_pub = self.create_publisher(String, '/speech_text', 10)

        def on_state(self, msg):
            if msg.data == 'listening':
                self.text_pub.publish(String(data='hello'))
                self.announce('heard')


    def main():
        rclpy.init()
        rclpy.spin(SpeechInput())
"""
SPEECH_CLOUD = SPEECH_LOCAL.replace("on this computer", "in the cloud")
ASSISTANT = """
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import String

    from voice.state import StateMixin


    class Assistant(StateMixin, Node):
        def __init__(self):
            super().__init__('assistant')
            self.setup_state()
            self.create_subscription(String, '/speech_text', self.on_text, 10)
            self.announce('listening')

        def on_text(self, msg):
            self.announce('thinking')


    def main():
        rclpy.init()
        rclpy.spin(Assistant())
"""
ENTRIES = ("'speech_local = voice.speech_local:main', 'speech_cloud = voice.speech_cloud:main', "
           "'assistant = voice.assistant:main'")


def _findings(tmp_path: Path, **modules: str) -> list[tuple[str, str, int]]:
    files = {"state": STATE, "speech_local": SPEECH_LOCAL, "speech_cloud": SPEECH_CLOUD,
             "assistant": ASSISTANT, **modules}
    root = write(tmp_path, package("voice", ENTRIES, files))
    report = build_report(root, Settings())
    return sorted((f.code, Path(f.location.path).name, f.location.line) for f in report.findings
                  if f.code in ("ROS002", "ROS007"))


def test_stages_sharing_a_state_channel_are_neither_loops_nor_run_together(tmp_path: Path) -> None:
    assert _findings(tmp_path) == []


def test_a_node_hearing_only_its_own_output_is_a_loop(tmp_path: Path) -> None:
    """The assistant leaves the channel: the speech inputs still publish and listen on it, but
    they are alternatives, one of them runs, and it hears only itself."""
    assistant = ASSISTANT.replace("StateMixin, Node", "Node").replace(
        "            self.setup_state()\n", "").replace("self.announce('listening')", "pass").replace(
        "self.announce('thinking')", "pass")
    found = _findings(tmp_path, assistant=assistant)
    assert ("ROS002", "state.py", 11) in found


def test_a_stage_listening_with_another_type_is_a_loop(tmp_path: Path) -> None:
    """A stage whose subscription has another type than what it publishes on the channel is a
    copy-paste slip, bus or not."""
    monitor = """
        import rclpy
        from rclpy.node import Node
        from std_msgs.msg import Int32, String


        class Monitor(Node):
            def __init__(self):
                super().__init__('monitor')
                self.state_pub = self.create_publisher(String, '/pipeline_state', 10)
                self.create_subscription(Int32, '/pipeline_state', self.on_state, 10)

            def on_state(self, msg):
                self.get_logger().info(str(msg.data))


        def main():
            rclpy.init()
            rclpy.spin(Monitor())
    """
    found = _findings(tmp_path, monitor=monitor)
    assert ("ROS002", "monitor.py", 10) in found
    assert not [f for f in found if f[0] == "ROS002" and f[1] == "state.py"]


def test_stages_of_one_name_that_also_talk_over_a_topic_run_together(tmp_path: Path) -> None:
    """The cloud input is renamed by a copy-paste slip to the assistant's name: the assistant
    subscribes to its text, an ordinary topic, so the two run together."""
    cloud = SPEECH_CLOUD.replace("super().__init__('speech_input')", "super().__init__('assistant')")
    found = _findings(tmp_path, speech_cloud=cloud)
    assert ("ROS007", "assistant.py", 10) in found and ("ROS007", "speech_cloud.py", 12) in found
