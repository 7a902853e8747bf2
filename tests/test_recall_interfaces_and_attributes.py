"""Names found on a sixth round of repositories outside every test set: the constants a
workspace's own interface files define (a ``Topics.msg`` naming every topic of a robot for
its nodes). Each on a realistic multi-file workspace, with a twin where following the code
must not invent a name.
"""
from __future__ import annotations

from pathlib import Path

from flake8_rosgraph import cache
from flake8_rosgraph.interfaces.catalogue import interface_files
from flake8_rosgraph.interfaces.constants import interface_constants
from flake8_rosgraph.options import Settings

from test_recall_globals_and_escapes import package
from test_recall_mechanisms import entities
from test_workspace_discovery import write

KINDS = ("publishers", "subscriptions", "clients")

# -- constants of the workspace's interface files ----------------------------------------------
MSGS_XML = """
    <?xml version="1.0"?>
    <package format="3">
      <name>auv_msgs</name>
      <version>0.1.0</version>
      <description>Messages and topic names of the vehicle</description>
      <maintainer email="crew@example.com">crew</maintainer>
      <license>BSD</license>
      <buildtool_depend>ament_cmake</buildtool_depend>
      <member_of_group>rosidl_interface_packages</member_of_group>
      <export><build_type>ament_cmake</build_type></export>
    </package>
"""
TOPICS_MSG = """
    # One place for the topic names every node of the vehicle uses.
    string DEPTH_TOPIC = 'core/depth'    # pressure sensor, metres
    string THRUSTER_CMD_TOPIC="core/thruster_cmd"
    string<=32 LEAK_TOPIC = core/leak
    string ODD_TOPIC = core/odd#1
    uint8 THRUSTERS = 2
"""
SETPOINT_SRV = """
    string SERVICE = 'control/set_depth'
    float64 depth
    ---
    bool accepted
"""
DEPTH_NODE = """
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import Bool, Float64

    from auv_msgs.msg import Topics
    from auv_msgs.srv import SetDepth


    class DepthController(Node):
        def __init__(self):
            super().__init__('depth_controller')
            self.create_subscription(Float64, Topics.DEPTH_TOPIC, self.on_depth, 10)
            self.create_subscription(Bool, Topics.LEAK_TOPIC, self.on_leak, 10)
            self.thrust = self.create_publisher(Float64, Topics.THRUSTER_CMD_TOPIC, 10)
            self.setpoint = self.create_client(SetDepth, SetDepth.Request.SERVICE)

        def on_depth(self, msg):
            pass

        def on_leak(self, msg):
            pass


    def main():
        rclpy.init()
        rclpy.spin(DepthController())
"""


def _vehicle(tmp_path: Path, node: str = DEPTH_NODE, topics: str = TOPICS_MSG) -> Path:
    """An interface package ``auv_msgs`` beside a Python package whose node names its topics
    by the message's constants."""
    files = {"auv_msgs/package.xml": MSGS_XML, "auv_msgs/msg/Topics.msg": topics,
             "auv_msgs/srv/SetDepth.srv": SETPOINT_SRV}
    files.update(package("auv_control", "'depth_controller = auv_control.depth:main'", {"depth": node}))
    return write(tmp_path / "ws", files)


def test_a_constant_of_the_workspaces_message_is_the_topic_name(tmp_path: Path) -> None:
    """``Topics.DEPTH_TOPIC`` is the text ``Topics.msg`` gives it, quoted either way, bounded
    or not; a service's request part holds its own (``SetDepth.Request.SERVICE``)."""
    root = _vehicle(tmp_path)
    assert entities(root, KINDS) == {"/depth_controller": [
        ("clients", "/control/set_depth"), ("publishers", "/core/thruster_cmd"),
        ("subscriptions", "/core/depth"), ("subscriptions", "/core/leak")]}


def test_a_constant_the_file_lacks_or_does_not_settle_stays_unknown(tmp_path: Path) -> None:
    """The twin: an attribute the message does not define, an unquoted text holding ``#``
    (a comment or the text?) and a class of the same name in a package the workspace does
    not define are never given a name."""
    node = DEPTH_NODE.replace("Topics.LEAK_TOPIC", "Topics.ODD_TOPIC") \
        .replace("Topics.THRUSTER_CMD_TOPIC", "Topics.THRUSTER_TOPIC") \
        .replace("from auv_msgs.srv", "from sub_msgs.msg import Topics as SubTopics\n    from auv_msgs.srv") \
        .replace("Topics.DEPTH_TOPIC", "SubTopics.DEPTH_TOPIC")
    root = _vehicle(tmp_path, node)
    assert entities(root, KINDS) == {"/depth_controller": [
        ("clients", "/control/set_depth"), ("publishers", "?"),
        ("subscriptions", "?"), ("subscriptions", "?")]}


def test_constants_are_read_as_rosidl_reads_them(tmp_path: Path) -> None:
    """Numbers and booleans by their type, a service's parts under both names rclpy gives
    their classes; a value that does not parse is left out."""
    root = _vehicle(tmp_path, topics=TOPICS_MSG + "bool ENABLED=true\nfloat32 GAIN=1e-2\nint8 BAD=x\n")
    found = interface_constants(interface_files(root, root))
    assert found["auv_msgs.msg.Topics.THRUSTERS"] == 2
    assert found["auv_msgs.msg.Topics.ENABLED"] is True
    assert found["auv_msgs.msg.Topics.GAIN"] == 0.01
    assert "auv_msgs.msg.Topics.BAD" not in found and "auv_msgs.msg.Topics.ODD_TOPIC" not in found
    assert found["auv_msgs.srv.SetDepth.Request.SERVICE"] == "control/set_depth"
    assert found["auv_msgs.srv.SetDepth_Request.SERVICE"] == "control/set_depth"


SENSOR_NODE = """
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import Bool, Float64


    def main():
        rclpy.init()
        node = Node('pressure_sensor')
        node.create_publisher(Float64, '/core/depth', 10)
        node.create_publisher(Bool, '/core/leak', 10)
        node.create_subscription(Float64, '/core/thruster_cmd', lambda msg: None, 10)
        rclpy.spin(node)
"""


def test_an_edit_of_a_constant_reanalyses_the_code_that_reads_it(tmp_path: Path) -> None:
    """The groups' kept facts depend on the constants: renaming a topic in ``Topics.msg``
    shows in the next run's report through the cache, although no Python file changed."""
    root = _vehicle(tmp_path)
    write(root, package("auv_sensors", "'pressure = auv_sensors.pressure:main'", {"pressure": SENSOR_NODE}))

    def codes() -> list[tuple[str, str]]:
        cache.start_run()
        report = cache.load_or_build(root, Settings())
        return sorted((f.location.path, f.code) for f in report.findings)

    assert codes() == []
    topics = root / "auv_msgs/msg/Topics.msg"
    topics.write_text(topics.read_text().replace("'core/depth'", "'core/depth_m'"))
    assert ("auv_control/auv_control/depth.py", "ROS003") in codes()


# -- the fallback of a failed message import ------------------------------------------------------
FALLBACK_NODE = """
    import rclpy
    from rclpy.node import Node

    try:
        from geometry_msgs.msg import Twist
        from vehicle_msgs.msg import MissionStatus
    except ImportError:  # tests on a machine without the messages
        Twist = None

        class MissionStatus:
            READY = 0
            status = 0

    from vehicle_control.topics import STATUS_TOPIC


    class GateMission(Node):
        def __init__(self):
            super().__init__('gate_mission')
            self.cmd = self.create_publisher(Twist, 'cmd_vel', 10)
            self.status = self.create_publisher(MissionStatus, STATUS_TOPIC, 10)


    def main():
        rclpy.init()
        rclpy.spin(GateMission())
"""


def _typed_publishers(tmp_path: Path, node: str) -> list[tuple[str, str]]:
    from flake8_rosgraph.analysis import build_graph
    root = write(tmp_path / "ws", package("vehicle_control", "'gate = vehicle_control.gate:main'",
                                          {"gate": node, "topics": "STATUS_TOPIC = 'mission/status'\n"}))
    [found] = build_graph(root).nodes
    return sorted((e.name or "?", e.type or "?") for e in found.entities if e.kind == "publishers")


def test_the_fallback_of_a_failed_message_import_is_no_type(tmp_path: Path) -> None:
    """``Twist = None`` and a stand-in class where the import failed create no publisher (rclpy
    refuses a type without type support): the publisher that exists has the message's type."""
    assert _typed_publishers(tmp_path, FALLBACK_NODE) == [
        ("/cmd_vel", "geometry_msgs/msg/Twist"), ("/mission/status", "vehicle_msgs/msg/MissionStatus")]


def test_a_workspace_class_alone_or_beside_an_unknown_is_no_type_either(tmp_path: Path) -> None:
    """The twin: where the stand-in is the only possibility, or the other possibility is not
    known, the type stays unknown rather than guessed."""
    node = FALLBACK_NODE.replace("        from vehicle_msgs.msg import MissionStatus\n", "") \
        .replace("from geometry_msgs.msg import Twist", "from geometry_msgs.msg import Twist\n"
                 "        import vehicle_drivers\n        Twist = vehicle_drivers.command_type()")
    assert _typed_publishers(tmp_path, node) == [("/cmd_vel", "?"), ("/mission/status", "?")]


# -- a setting's text with the whitespace around it dropped ----------------------------------------
STRIPPED_NODE = """
    import rclpy
    from rclpy.node import Node
    from rclpy.parameter import Parameter
    from std_msgs.msg import String


    class VoiceActivity(Node):
        def __init__(self):
            super().__init__('voice_activity')
            self.declare_parameter('audio_topic', Parameter.Type.STRING)
            self.declare_parameter('output_topic', 'voice/activity')
            self.create_subscription(String, self._required_text('audio_topic'), self.on_audio, 10)
            self.create_publisher(String, self._required_text('output_topic'), 10)
            self.create_publisher(String, self.get_parameter('output_topic').value.strip('/') + '_raw', 10)

        def _required_text(self, name):
            parameter = self.get_parameter(name)
            if parameter.type_ != Parameter.Type.STRING:
                raise RuntimeError(f'{name} must be a string')
            text = str(parameter.value).strip()
            if not text:
                raise RuntimeError(f'{name} is required')
            return text

        def on_audio(self, msg):
            pass


    def main():
        rclpy.init()
        rclpy.spin(VoiceActivity())
"""
VOICE_LAUNCH = """
    from launch import LaunchDescription
    from launch_ros.actions import Node


    def generate_launch_description():
        return LaunchDescription([
            Node(package='voice', executable='activity',
                 parameters=[{'audio_topic': 'mic/frames', 'output_topic': '/speech/activity'}]),
        ])
"""


def test_a_stripped_setting_is_still_the_setting_a_launch_file_sets(tmp_path: Path) -> None:
    """``str(param.value).strip()`` in a helper is the parameter still: in code the name without
    a default is unknown and the one with a default is the default, and the launch file's
    values name both. ``strip('/')`` (which drops text) and what is joined to it are not the
    setting: under the launch file that name stays the code's."""
    from flake8_rosgraph.analysis import build_graph
    from test_parameter_named_entities import launched, named

    files = package("voice", "'activity = voice.activity:main'", {"activity": STRIPPED_NODE})
    files["voice/launch/voice.launch.py"] = VOICE_LAUNCH
    graph = build_graph(write(tmp_path / "ws", files))
    assert named(graph, "/voice_activity") == {
        12: {(None, "audio_topic")}, 13: {("/voice/activity", "output_topic")}, 14: {("/voice/activity_raw", None)}}
    assert launched(graph, "voice.launch.py")["/voice_activity"] == {
        12: {("/mic/frames", "audio_topic")}, 13: {("/speech/activity", "output_topic")},
        14: {("/voice/activity_raw", None)}}


def test_a_stripped_default_with_spaces_is_the_stripped_text(tmp_path: Path) -> None:
    """The twin: a default written with spaces around it (``' voice/activity '``) is a setting
    whose text ``strip()`` changes: the name is the stripped text, not the default as written."""
    from flake8_rosgraph.analysis import build_graph
    from test_parameter_named_entities import named

    node = STRIPPED_NODE.replace("'output_topic', 'voice/activity'", "'output_topic', ' voice/activity '")
    graph = build_graph(write(tmp_path / "ws", package("voice", "'activity = voice.activity:main'",
                                                       {"activity": node})))
    assert {name for name, _ in named(graph, "/voice_activity")[13]} == {"/voice/activity"}


# -- an attribute read back where the function just stored it ---------------------------------------
CAMERA_NODE = """
    import sys

    import rclpy
    from rclpy.node import Node
    from sensor_msgs.msg import CameraInfo, Image
    from std_msgs.msg import String

    from camera_tools.streams import stream_topic


    class PointCloudService(Node):
        def __init__(self):
            super().__init__('pointcloud_service')
            self.declare_parameter('camera_name', 'd415')
            self.camera_name = self.get_parameter('camera_name').value
            self.declare_parameter('rate', 10.0)
            prefix = f'/fv/{self.camera_name}'
            self.depth_sub = self.create_subscription(Image, f'{prefix}/depth', self.on_depth, 10)
            self.status_topic = 'status'
            self.status = self.create_publisher(String, self.status_topic, 10)
            if self.camera_name.startswith('d4'):
                self.info_topic = stream_topic(self.camera_name, 'info')
            self.info = self.create_subscription(CameraInfo, self.info_topic, self.on_info, 10)

        def on_depth(self, msg):
            self.status_topic = msg.header.frame_id

        def on_info(self, msg):
            pass


    def main():
        rclpy.init()
        node = PointCloudService()
        if len(sys.argv) > 1:
            node.camera_name = sys.argv[1]
        rclpy.spin(node)
"""
STREAMS_MODULE = """
    def stream_topic(camera, stream):
        return f'/{camera}/{stream}'
"""


def _camera(tmp_path: Path, node: str) -> dict[str, list[tuple[str, str]]]:
    root = write(tmp_path / "ws", package("camera_tools", "'pointcloud = camera_tools.pointcloud:main'",
                                          {"pointcloud": node, "streams": STREAMS_MODULE}))
    return entities(root, ("publishers", "subscriptions"))


def test_an_attribute_is_read_back_as_the_function_just_stored_it(tmp_path: Path) -> None:
    """``self.camera_name`` right after ``__init__`` stored the parameter is the parameter,
    not also the command-line value ``main`` stores later; ``self.status_topic`` is
    ``'status'``, not also the frame id a callback stores (the library calls in between store
    nothing on the node)."""
    found = _camera(tmp_path, CAMERA_NODE)
    assert found == {"/pointcloud_service": [
        ("publishers", "/status"), ("subscriptions", "/d415/info"), ("subscriptions", "/fv/d415/depth")]}


def test_an_attribute_a_call_in_between_may_have_stored_is_not_remembered(tmp_path: Path) -> None:
    """The twin: after a call of the node's own method (which may store any attribute), every
    read is the heap's join again — the status topic is ``'status'``, ``'diagnostics'`` or a
    callback's frame id, the camera name possibly ``main``'s unknown one — never the value
    stored before the call alone."""
    node = CAMERA_NODE.replace(
        "            self.status = self.create_publisher(String, self.status_topic, 10)\n",
        "            self.configure()\n"
        "            self.status = self.create_publisher(String, self.status_topic, 10)\n") \
        .replace("        def on_info(self, msg):\n", "        def configure(self):\n"
                 "            self.status_topic = 'diagnostics'\n\n"
                 "        def on_info(self, msg):\n")
    assert _camera(tmp_path, node) == {"/pointcloud_service": [
        ("publishers", "/diagnostics"), ("publishers", "/status"), ("publishers", "?"),
        ("subscriptions", "/d415/info"), ("subscriptions", "/fv/d415/depth"), ("subscriptions", "?")]}


def test_a_store_on_some_paths_only_joins_with_what_was_there(tmp_path: Path) -> None:
    """The other twin: a store on one branch is remembered beside the earlier store of the
    other path, and a property's setter is no plain store: its getter is read."""
    node = CAMERA_NODE.replace(
        "            self.status = self.create_publisher(String, self.status_topic, 10)\n",
        "            if self.has_parameter('verbose'):\n"
        "                self.status_topic = 'status/verbose'\n"
        "            self.status = self.create_publisher(String, self.status_topic, 10)\n"
        "            self.depth_topic = 'depth'\n"
        "            self.create_publisher(Image, self.depth_topic, 10)\n") \
        .replace("        def on_info(self, msg):\n", "        @property\n"
                 "        def depth_topic(self):\n"
                 "            return f'/{self.camera_name}/{self._depth}'\n\n"
                 "        @depth_topic.setter\n"
                 "        def depth_topic(self, value):\n"
                 "            self._depth = value\n\n"
                 "        def on_info(self, msg):\n")
    publishers = sorted(name for kind, name in _camera(tmp_path, node)["/pointcloud_service"]
                        if kind == "publishers")
    assert publishers == ["/d415/depth", "/status", "/status/verbose", "?"]


# -- the values pytest's parametrize lists for a test ------------------------------------------
PROBE_CLIENT = """
    import rclpy
    from geometry_msgs.msg import TwistStamped
    from nav_msgs.msg import Odometry


    class CommandProbe:
        def __init__(self, robot_name):
            self.node = rclpy.create_node(f'{robot_name}_probe')
            self.commands = self.node.create_publisher(TwistStamped, f'/{robot_name}/reference', 10)
            self.odometry = self.node.create_subscription(
                Odometry, f'/{robot_name}/odometry', self.on_odometry, 10)

        def on_odometry(self, msg):
            self.latest = msg
"""
PROBE_TEST = """
    import pytest
    import rclpy

    from vehicle_tests.probe import CommandProbe


    @pytest.mark.parametrize('vehicle', ['ackermann', 'mecanum'])
    def test_the_vehicle_takes_commands(vehicle):
        rclpy.init()
        probe = CommandProbe(f'{vehicle}_runtime')
        assert probe.node.count_subscribers(f'/{vehicle}_runtime/reference') == 1
"""


def _probes(tmp_path: Path, test: str) -> dict[str | None, list[tuple[str, str]]]:
    root = write(tmp_path / "ws", {**package("vehicle_tests", "", {"probe": PROBE_CLIENT}),
                                   "vehicle_tests/test/test_runtime.py": test})
    return entities(root, ("publishers", "subscriptions"))


def test_each_listed_value_of_a_parametrized_test_keeps_its_own_names(tmp_path: Path) -> None:
    """pytest runs the test once per listed vehicle: each run's probe node has that vehicle's
    topics only (the values are not joined, which would give every node both)."""
    assert _probes(tmp_path, PROBE_TEST) == {
        "/ackermann_runtime_probe": [("publishers", "/ackermann_runtime/reference"),
                                     ("subscriptions", "/ackermann_runtime/odometry")],
        "/mecanum_runtime_probe": [("publishers", "/mecanum_runtime/reference"),
                                   ("subscriptions", "/mecanum_runtime/odometry")]}


def test_values_listed_in_rows_or_too_many_stay_unknown(tmp_path: Path) -> None:
    """The twin: rows for two parameters, and more combinations than a function's contexts
    keep, leave the names unknown rather than pair them wrongly."""
    rows = PROBE_TEST.replace("@pytest.mark.parametrize('vehicle', ['ackermann', 'mecanum'])",
                              "@pytest.mark.parametrize('vehicle, wheels', [('ackermann', 4), ('mecanum', 4)])") \
        .replace("(vehicle)", "(vehicle, wheels)")
    unknown = {None: [("publishers", "?"), ("subscriptions", "?")]}
    assert _probes(tmp_path / "rows", rows) == unknown
    many = PROBE_TEST.replace("@pytest.mark.parametrize('vehicle', ['ackermann', 'mecanum'])",
                              "@pytest.mark.parametrize('vehicle', ['a', 'b', 'c', 'd', 'e'])\n"
                              "    @pytest.mark.parametrize('speed', [1, 2, 3, 4, 5])") \
        .replace("(vehicle)", "(vehicle, speed)")
    assert _probes(tmp_path / "many", many) == unknown
