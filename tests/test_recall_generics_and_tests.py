"""Extraction mechanisms found on a third round of real repositories outside every test set
(generic connector classes, package modules with a ``#!`` line, unittest test cases, wrapper
classes named like rclpy's), each on a realistic multi-file workspace, with a near-identical
twin where following the code must not invent a name or an entity."""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from flake8_rosgraph.analysis import analyse, build_graph
from flake8_rosgraph.explain import explain
from flake8_rosgraph.launch.api import judged_graph

from test_recall_mechanisms import entities, explained, findings
from test_workspace_discovery import PACKAGE_XML, setup_py, write


# -- generic classes: ``Base[T]`` as a base class and ``Connector[Msg](...)`` -----------------------
CONNECTOR_FILES = {
    "agent_comm/package.xml": PACKAGE_XML.format(name="agent_comm", build="ament_python"),
    "agent_comm/setup.py": setup_py("agent_comm", "'agent = agent_comm.agent:main'"),
    "agent_comm/agent_comm/__init__.py": "",
    "agent_comm/agent_comm/base.py": """
        from typing import Generic, TypeVar

        T = TypeVar('T')


        class BaseConnector(Generic[T]):
            '''Transport-agnostic: sends and receives messages of type T.'''

            def __init__(self):
                self.sent = []
    """,
    "agent_comm/agent_comm/ros_connector.py": """
        from typing import TypeVar

        from rclpy.node import Node
        from std_srvs.srv import Trigger

        from agent_comm.base import BaseConnector

        M = TypeVar('M')


        class RosConnectorBase(BaseConnector[M]):
            def __init__(self, node_name):
                super().__init__()
                self._node = Node(node_name)
                self._node.create_service(Trigger, '~/reset', self.on_reset)

            @property
            def node(self):
                return self._node

            def on_reset(self, request, response):
                self.sent.clear()
                return response
    """,
    "agent_comm/agent_comm/connectors.py": """
        from std_msgs.msg import String

        from agent_comm.ros_connector import RosConnectorBase


        class StringConnector(RosConnectorBase[String]):
            pass
    """,
    "agent_comm/agent_comm/agent.py": """
        import rclpy
        from std_msgs.msg import String

        from agent_comm.connectors import StringConnector
        from agent_comm.ros_connector import RosConnectorBase


        class Speaker:
            def __init__(self, connector):
                self.connector = connector
                self.pub = self.connector.node.create_publisher(String, '/speech/say', 10)


        def main():
            rclpy.init()
            speaker = Speaker(StringConnector('speaker'))
            listener = RosConnectorBase[String]('listener')
            listener.node.create_subscription(String, '/speech/heard', print, 10)
            rclpy.spin(speaker.connector.node)
    """,
}


def test_a_generic_base_class_and_a_subscripted_constructor_are_the_class(tmp_path: Path) -> None:
    """``class StringConnector(RosConnectorBase[String])`` derives from ``RosConnectorBase``,
    itself a ``BaseConnector[M]`` over ``Generic[T]``, and ``RosConnectorBase[String](…)``
    builds one: typing's aliases stand for the class (rai's ROS2Connector: 6 sites never
    reached and 13 on ``connector.node`` before)."""
    got = entities(write(tmp_path, CONNECTOR_FILES))
    assert got == {
        "/listener": [("services", "/listener/reset"), ("subscriptions", "/speech/heard")],
        "/speaker": [("publishers", "/speech/say"), ("services", "/speaker/reset")],
    }


def test_a_class_whose_subscript_runs_code_is_not_an_alias(tmp_path: Path) -> None:
    """An ``Enum``'s or a metaclass's ``Cls[key]`` runs code of its own (``Topics['cmd']`` is a
    member, ``Lookup['x']`` whatever ``__getitem__`` returns): no name comes from taking it
    for the class."""
    files = dict(CONNECTOR_FILES)
    files["agent_comm/agent_comm/names.py"] = """
        from enum import Enum


        class Topics(Enum):
            CMD = '/speech/cmd'


        class Registry(type):
            def __getitem__(cls, key):
                return cls.table[key]


        class Lookup(metaclass=Registry):
            table = {}
    """
    files["agent_comm/agent_comm/agent.py"] = """
        import rclpy
        from rclpy.node import Node
        from std_msgs.msg import String

        from agent_comm.names import Lookup, Topics


        def main():
            rclpy.init()
            node = Node('speaker')
            node.create_publisher(String, Topics['CMD'], 10)
            node.create_publisher(String, Lookup['say'], 10)
            rclpy.spin(node)
    """
    got = entities(write(tmp_path, files))
    assert got["/speaker"] == [("publishers", "?"), ("publishers", "?")]


# -- a package module with a ``#!`` line, named like its package ------------------------------------
CAMERA_FILES = {
    "ptz_camera/package.xml": PACKAGE_XML.format(name="ptz_camera", build="ament_python"),
    "ptz_camera/setup.py": setup_py("ptz_camera", "'ptz_camera_node = ptz_camera.ptz_camera_node:main'"),
    "ptz_camera/ptz_camera/__init__.py": "",
    "ptz_camera/ptz_camera/ptz.py": """
        from std_msgs.msg import Float32


        class Ptz:
            '''Pan/tilt control, created by the camera node on itself.'''

            def __init__(self, node):
                self.node = node
                self.cmd_sub = node.create_subscription(Float32, 'ptz/pan', self.on_pan, 1)
                self.state_pub = node.create_publisher(Float32, 'ptz/state', 1)

            def on_pan(self, msg):
                self.state_pub.publish(msg)
    """,
    "ptz_camera/ptz_camera/ptz_camera.py": """
        #!/usr/bin/env python3
        from rclpy.node import Node
        from sensor_msgs.msg import CompressedImage

        from ptz_camera.ptz import Ptz


        class PtzCamera(Node):
            def __init__(self):
                super().__init__('ptz_camera')
                self.image_pub = self.create_publisher(CompressedImage, 'image/compressed', 1)
                self.ptz = Ptz(self)
    """,
    "ptz_camera/ptz_camera/ptz_camera_node.py": """
        #!/usr/bin/env python3
        import rclpy

        from ptz_camera.ptz_camera import PtzCamera


        def main():
            rclpy.init()
            rclpy.spin(PtzCamera())
    """,
}


def test_a_package_module_with_a_shebang_imports_its_package_by_name(tmp_path: Path) -> None:
    """``ptz_camera/ptz_camera.py`` has a ``#!`` line but runs through the package (a console
    script imports it): ``from ptz_camera.ptz import Ptz`` is the package's module, not an
    attribute of the file itself (axis_camera: 6 sites never reached before)."""
    root = write(tmp_path, CAMERA_FILES)
    assert entities(root) == {"/ptz_camera": [
        ("publishers", "/image/compressed"), ("publishers", "/ptz/state"),
        ("subscriptions", "/ptz/pan")]}
    assert all(status == "complete" for _, _, status in explained(root))


def test_a_package_module_with_a_shebang_still_imports_its_neighbour(tmp_path: Path) -> None:
    """The same file importing another name (``import ptz``): a ``#!`` file's own folder comes
    first on ``sys.path``, so the module beside it is taken, as before."""
    files = dict(CAMERA_FILES)
    files["ptz_camera/ptz_camera/ptz_camera.py"] = CAMERA_FILES["ptz_camera/ptz_camera/ptz_camera.py"] \
        .replace("from ptz_camera.ptz import Ptz", "from ptz import Ptz")
    assert entities(write(tmp_path, files))["/ptz_camera"] == [
        ("publishers", "/image/compressed"), ("publishers", "/ptz/state"),
        ("subscriptions", "/ptz/pan")]


# -- unittest test cases: the runner instantiates them ----------------------------------------------
FILTER_FILES = {
    "scan_filter/package.xml": PACKAGE_XML.format(name="scan_filter", build="ament_python"),
    "scan_filter/setup.py": setup_py("scan_filter", "'scan_filter = scan_filter.filter_node:main'"),
    "scan_filter/scan_filter/__init__.py": "",
    "scan_filter/scan_filter/filter_node.py": """
        import rclpy
        from rclpy.node import Node
        from sensor_msgs.msg import LaserScan


        class ScanFilter(Node):
            def __init__(self):
                super().__init__('scan_filter')
                self.pub = self.create_publisher(LaserScan, 'scan_filtered', 10)
                self.create_subscription(LaserScan, 'scan', self.pub.publish, 10)


        def main():
            rclpy.init()
            rclpy.spin(ScanFilter())
    """,
    "scan_filter/test/probes.py": """
        import unittest

        import rclpy
        from sensor_msgs.msg import LaserScan
        from std_srvs.srv import Empty


        class ProbeTestBase(unittest.TestCase):
            '''Shared by the filter's tests; each sets its probe's name.'''

            probe_name = None

            @classmethod
            def setUpClass(cls):
                rclpy.init()
                cls.node = rclpy.create_node(cls.probe_name)

            def setUp(self):
                self.scan_pub = self.node.create_publisher(LaserScan, 'scan', 10)
                self.received = []
                self.node.create_subscription(LaserScan, 'scan_filtered', self.received.append, 10)

            @classmethod
            def tearDownClass(cls):
                cls.node.destroy_node()
                rclpy.shutdown()
    """,
    "scan_filter/test/test_filter.py": """
        from std_srvs.srv import Empty

        from probes import ProbeTestBase


        class TestPassThrough(ProbeTestBase):
            probe_name = 'pass_through_probe'

            def test_scan_passes(self):
                self.scan_pub.publish(self.make_scan())
                self.assertTrue(self.received)

            def make_scan(self):
                from sensor_msgs.msg import LaserScan
                return LaserScan()


        class TestReset(ProbeTestBase):
            probe_name = 'reset_probe'

            def test_reset(self):
                client = self.node.create_client(Empty, 'scan_filter/reset')
                self.assertTrue(client.wait_for_service(timeout_sec=1.0))
    """,
}


def test_unittest_cases_are_entry_points(tmp_path: Path) -> None:
    """The test runner instantiates each leaf ``TestCase`` and runs ``setUpClass``, ``setUp``
    and the ``test_*`` methods: the probes' nodes and ends are in the graph under the names
    each subclass sets, and the shared base (never run on its own) invents no node named
    ``None`` (launch tests of ros2_control and FlexBE: 19 sites never reached before)."""
    root = write(tmp_path, FILTER_FILES)
    got = entities(root, ("publishers", "subscriptions", "clients"))
    assert got == {
        "/pass_through_probe": [("publishers", "/scan"), ("subscriptions", "/scan_filtered")],
        "/reset_probe": [("clients", "/scan_filter/reset"), ("publishers", "/scan"),
                         ("subscriptions", "/scan_filtered")],
        "/scan_filter": [("publishers", "/scan_filtered"), ("subscriptions", "/scan")],
    }
    assert all(status == "complete" for _, _, status in explained(root))


def test_a_class_with_test_methods_but_no_test_case_base_is_not_run(tmp_path: Path) -> None:
    """A helper with ``setUp``/``test_*``-like methods that is no ``TestCase`` (and that nothing
    instantiates) is not run by any runner: no node of it appears."""
    files = dict(FILTER_FILES)
    files["scan_filter/test/probes.py"] = FILTER_FILES["scan_filter/test/probes.py"].replace(
        "class ProbeTestBase(unittest.TestCase):", "class ProbeTestBase:")
    got = entities(write(tmp_path, files), ("publishers", "subscriptions", "clients"))
    assert list(got) == ["/scan_filter"]


# -- the workspace's own methods named like rclpy's ---------------------------------------------------
API_FILES = {
    "speech/package.xml": PACKAGE_XML.format(name="speech", build="ament_python"),
    "speech/setup.py": setup_py("speech", "'speech = speech.app:main'"),
    "speech/speech/__init__.py": "",
    "speech/speech/topic_api.py": """
        from std_msgs.msg import String


        class TopicAPI:
            '''Publishes strings by topic name, one publisher per topic.'''

            def __init__(self, node):
                self.node = node
                self.publishers = {}

            def create_publisher(self, topic):
                self.publishers[topic] = self.node.create_publisher(String, topic, 10)
                return self.publishers[topic]
    """,
    "speech/speech/app.py": """
        import rclpy
        from rclpy.node import Node

        from speech.topic_api import TopicAPI


        def main():
            rclpy.init()
            node = Node('speech')
            api = TopicAPI(node)
            api.create_publisher('/speech/say')
            rclpy.spin(node)
    """,
}


def test_a_wrapper_method_named_like_rclpys_is_no_creation_site(tmp_path: Path) -> None:
    """``api.create_publisher('/speech/say')`` calls the workspace's ``TopicAPI`` method: the
    site is the rclpy call inside it, not the call of the wrapper (which --explain used to
    list as "not in the graph")."""
    root = write(tmp_path, API_FILES)
    assert entities(root) == {"/speech": [("publishers", "/speech/say")]}
    assert explained(root) == [("speech/speech/app.py", 9, "complete"),
                               ("speech/speech/topic_api.py", 12, "complete")]


def test_a_create_call_on_an_unknown_object_stays_a_site(tmp_path: Path) -> None:
    """The same call on an object the analysis does not know (here from an unresolved import)
    may be rclpy's: it stays listed, as not in the graph."""
    files = dict(API_FILES)
    files["speech/speech/app.py"] = API_FILES["speech/speech/app.py"].replace(
        "from speech.topic_api import TopicAPI", "from speech_vendor import TopicAPI")
    assert ("speech/speech/app.py", 11, "missing") in explained(write(tmp_path, files))


# -- classes whose __init__ is built from their fields --------------------------------------------
LIDAR_FILES = {
    "lidar_bringup/package.xml": PACKAGE_XML.format(name="lidar_bringup", build="ament_python"),
    "lidar_bringup/setup.py": setup_py("lidar_bringup", "'lidars = lidar_bringup.lidars:main'"),
    "lidar_bringup/lidar_bringup/__init__.py": "",
    "lidar_bringup/lidar_bringup/config.py": """
        from dataclasses import dataclass, field
        from typing import ClassVar


        @dataclass
        class LidarConfig:
            topic: str = 'scan'
            frame_id: str = 'laser'
            MAX_RANGE: ClassVar[float] = 30.0


        @dataclass(frozen=True)
        class FilteredLidarConfig(LidarConfig):
            filtered_topic: str = 'scan_filtered'
            masks: list = field(default_factory=list)
    """,
    "lidar_bringup/lidar_bringup/lidars.py": """
        import rclpy
        from rclpy.node import Node
        from sensor_msgs.msg import LaserScan

        from lidar_bringup.config import FilteredLidarConfig, LidarConfig


        class LidarHub(Node):
            def __init__(self, configs, filtered):
                super().__init__('lidar_hub')
                for config in configs:
                    self.create_subscription(LaserScan, config.topic, self.on_scan, 10)
                self.create_publisher(LaserScan, filtered.filtered_topic, 10)

            def on_scan(self, msg):
                pass


        def main():
            rclpy.init()
            configs = [LidarConfig(topic='front/scan'), LidarConfig('rear/scan', 'rear_laser')]
            rclpy.spin(LidarHub(configs, FilteredLidarConfig('top/scan', filtered_topic='top/clean')))
    """,
}


def test_a_dataclass_instance_has_the_fields_it_was_built_with(tmp_path: Path) -> None:
    """``LidarConfig(topic='front/scan')`` and ``LidarConfig('rear/scan', …)`` set ``topic`` on
    the instance, by keyword and by position, base fields first for a dataclass subclass: the
    class-level ``'scan'`` is only the default (before, every subscription was named ``/scan``,
    a confident wrong name)."""
    assert entities(write(tmp_path, LIDAR_FILES)) == {"/lidar_hub": [
        ("publishers", "/top/clean"),
        ("subscriptions", "/front/scan"), ("subscriptions", "/rear/scan")]}


def test_a_field_left_out_keeps_its_default_and_a_plain_class_is_unchanged(tmp_path: Path) -> None:
    """``LidarConfig()`` keeps ``'scan'``; a class with its own ``__init__`` that never sets
    ``topic`` still reads its class attribute; a ``**kwargs`` call leaves every field it
    may set unknown, never the default."""
    files = dict(LIDAR_FILES)
    files["lidar_bringup/lidar_bringup/lidars.py"] = LIDAR_FILES["lidar_bringup/lidar_bringup/lidars.py"] \
        .replace("configs = [LidarConfig(topic='front/scan'), LidarConfig('rear/scan', 'rear_laser')]",
                 "configs = [LidarConfig(), Legacy('rear/scan'), LidarConfig(**load())]") \
        .replace("from lidar_bringup.config import FilteredLidarConfig, LidarConfig",
                 "from lidar_bringup.config import FilteredLidarConfig, LidarConfig\n"
                 "        from lidar_bringup.loader import load\n\n\n"
                 "        class Legacy:\n"
                 "            topic: str = 'legacy/scan'\n\n"
                 "            def __init__(self, frame_id):\n"
                 "                self.frame_id = frame_id")
    files["lidar_bringup/lidar_bringup/loader.py"] = """
        import yaml


        def load():
            with open('/etc/lidars.yaml') as f:
                return yaml.safe_load(f)
    """
    assert entities(write(tmp_path, files)) == {"/lidar_hub": [
        ("publishers", "/top/clean"), ("subscriptions", "/legacy/scan"),
        ("subscriptions", "/scan"), ("subscriptions", "?")]}


TOOL_FILES = {
    "arm_tools/package.xml": PACKAGE_XML.format(name="arm_tools", build="ament_python"),
    "arm_tools/setup.py": setup_py("arm_tools", "'arm_agent = arm_tools.agent:main'"),
    "arm_tools/arm_tools/__init__.py": "",
    "arm_tools/arm_tools/tools.py": """
        from agent_framework.tools import BaseTool
        from std_srvs.srv import Trigger


        class RosTool(BaseTool):
            '''A tool of the agent framework (a pydantic model): fields by keyword.'''

            node: object
            service_name: str = 'arm/home'

            def run(self):
                client = self.node.create_client(Trigger, self.service_name)
                return client.call_async(Trigger.Request())
    """,
    "arm_tools/arm_tools/agent.py": """
        import rclpy
        from rclpy.node import Node

        from arm_tools.tools import RosTool


        def main():
            rclpy.init()
            node = Node('arm_agent')
            tools = [RosTool(node=node), RosTool(node=node, service_name='gripper/open')]
            for tool in tools:
                tool.run()
            rclpy.spin(node)
    """,
}


def test_keywords_naming_fields_of_a_framework_model_set_them(tmp_path: Path) -> None:
    """A class over a library base no stub models (a pydantic model behind an agent
    framework's ``BaseTool``) called with keywords that name its annotated fields has them
    set: ``tool.node`` is the node, and each tool's service is its own (rai's tools: the
    connector's node was unknown before)."""
    assert entities(write(tmp_path, TOOL_FILES), ("clients",)) == {"/arm_agent": [
        ("clients", "/arm/home"), ("clients", "/gripper/open")]}


# -- callable objects and classes with their own __new__ -------------------------------------------
RELAY_FILES = {
    "topic_relay/package.xml": PACKAGE_XML.format(name="topic_relay", build="ament_python"),
    "topic_relay/setup.py": setup_py("topic_relay", "'relay = topic_relay.relay_node:main'"),
    "topic_relay/topic_relay/__init__.py": "",
    "topic_relay/topic_relay/functors.py": """
        from std_msgs.msg import String


        class Forward:
            '''Republishes what it receives; the publisher is made on the first message.'''

            def __init__(self, node, out_topic):
                self.node = node
                self.out_topic = out_topic
                self.pub = None

            def __call__(self, msg):
                if self.pub is None:
                    self.pub = self.node.create_publisher(String, self.out_topic, 10)
                self.pub.publish(msg)
    """,
    "topic_relay/topic_relay/clients.py": """
        from std_srvs.srv import Trigger


        class SharedClient:
            '''One client per service name for the whole process.'''

            _clients = {}

            def __new__(cls, node, service_name):
                if service_name not in cls._clients:
                    instance = super().__new__(cls)
                    instance.client = node.create_client(Trigger, service_name)
                    cls._clients[service_name] = instance
                return cls._clients[service_name]

            def call(self):
                return self.client.call_async(Trigger.Request())
    """,
    "topic_relay/topic_relay/relay_node.py": """
        import rclpy
        from rclpy.node import Node
        from std_msgs.msg import String

        from topic_relay.clients import SharedClient
        from topic_relay.functors import Forward

        ROUTES = [('radio/in', 'radio/out'), ('wifi/in', 'wifi/out')]


        class RelayNode(Node):
            def __init__(self):
                super().__init__('relay')
                for source, target in ROUTES:
                    self.create_subscription(String, source, Forward(self, target), 10)
                self.reset = SharedClient(self, 'relay/reset')


        def main():
            rclpy.init()
            rclpy.spin(RelayNode())
    """,
}


def test_callable_objects_run_as_callbacks_and_new_builds_the_instance(tmp_path: Path) -> None:
    """A ``Forward(self, target)`` instance handed over as the callback runs its ``__call__``
    (its publishers are in the graph), and ``SharedClient(self, …)`` runs the class's
    ``__new__``, whose ``super().__new__(cls)`` makes the instance (ros2_control's
    SingletonServiceCaller: never reached before)."""
    assert entities(write(tmp_path, RELAY_FILES), ("publishers", "subscriptions", "clients")) == {
        "/relay": [("clients", "/relay/reset"),
                   ("publishers", "/radio/out"), ("publishers", "/wifi/out"),
                   ("subscriptions", "/radio/in"), ("subscriptions", "/wifi/in")]}


def test_init_does_not_run_on_what_new_returns_of_another_class(tmp_path: Path) -> None:
    """Python runs ``__init__`` only on an instance of the class: a ``__new__`` returning
    the client itself skips it, and an object without ``__call__`` handed over as a
    callback runs nothing."""
    files = dict(RELAY_FILES)
    files["topic_relay/topic_relay/clients.py"] = """
        from std_msgs.msg import String
        from std_srvs.srv import Trigger


        class SharedClient:
            def __new__(cls, node, service_name):
                return node.create_client(Trigger, service_name)

            def __init__(self, node, service_name):
                node.create_publisher(String, 'never_made', 1)
    """
    files["topic_relay/topic_relay/functors.py"] = RELAY_FILES["topic_relay/topic_relay/functors.py"] \
        .replace("def __call__(self, msg):", "def _forward(self, msg):")
    assert entities(write(tmp_path, files), ("publishers", "subscriptions", "clients")) == {
        "/relay": [("clients", "/relay/reset"),
                   ("subscriptions", "/radio/in"), ("subscriptions", "/wifi/in")]}


def test_an_attribute_of_objects_some_unknown_is_the_same_on_every_run(tmp_path: Path) -> None:
    """``config.topic`` over configs of which one is built from unknown keywords: the known
    names are kept beside the unknown one whatever order the set of objects is walked in
    (it follows string hashing, which changes between runs)."""
    files = dict(LIDAR_FILES)
    files["lidar_bringup/lidar_bringup/lidars.py"] = LIDAR_FILES["lidar_bringup/lidar_bringup/lidars.py"] \
        .replace("configs = [LidarConfig(topic='front/scan'), LidarConfig('rear/scan', 'rear_laser')]",
                 "configs = [LidarConfig(), LidarConfig('rear/scan'), LidarConfig(**dict(os.environ))]") \
        .replace("import rclpy", "import os\n\n        import rclpy")
    root = write(tmp_path / "ws", files)
    outputs = set()
    for seed in ("1", "2", "3", "4"):
        env = {**os.environ, "PYTHONHASHSEED": seed, "ROSGRAPH_CACHE_DIR": str(tmp_path / f"cache{seed}")}
        outputs.add(subprocess.run([sys.executable, "-m", "flake8_rosgraph", "graph", str(root)],
                                   env=env, capture_output=True, check=True).stdout)
    assert len(outputs) == 1
    assert b'"/rear/scan"' in outputs.pop()


# -- str() of a parameter's value, ros2cli's NodeStrategy.direct_node ---------------------------------
PLAYER_FILES = {
    "archive_player/package.xml": PACKAGE_XML.format(name="archive_player", build="ament_python"),
    "archive_player/setup.py": setup_py("archive_player", "'player = archive_player.player:main'"),
    "archive_player/archive_player/__init__.py": "",
    "archive_player/archive_player/player.py": """
        import rclpy
        from rclpy.node import Node
        from sensor_msgs.msg import Image


        class Player(Node):
            def __init__(self):
                super().__init__('player')
                self.declare_parameter('image_topic')
                try:
                    self.image_topic = str(self.get_parameter('image_topic').value)
                except Exception:
                    self.get_logger().error('image_topic is not set')
                self.image_pub = self.create_publisher(Image, self.image_topic, 10)
                self.create_publisher(Image, str(self.get_parameter('image_topic').value) + '/raw', 10)


        def main():
            rclpy.init()
            rclpy.spin(Player())
    """,
    "archive_player/launch/play.launch.py": """
        from launch import LaunchDescription
        from launch_ros.actions import Node


        def generate_launch_description():
            return LaunchDescription([
                Node(package='archive_player', executable='player',
                     parameters=[{'image_topic': '/sim_camera/color_image'}]),
            ])
    """,
}


def test_str_of_a_text_parameter_is_still_that_parameter(tmp_path: Path) -> None:
    """``str(self.get_parameter('image_topic').value)`` is the parameter's text: the entity is
    named by the parameter (a launch file that sets it names the topic), not "a value the
    analysis does not know" (industrial_reconstruction: 6 sites), and text joined to it is
    rebuilt from the launch file's value too."""
    graph = build_graph(write(tmp_path, PLAYER_FILES))
    player = next(n for n in graph.nodes if n.fqn == "/player")
    assert sorted(((e.name, e.from_parameter) for e in player.entities if e.kind == "publishers"),
                  key=repr) == [(None, "image_topic"), (None, None)]
    system = next(s for s in graph.systems if s.launch_file.endswith("play.launch.py"))
    launched = next(n for n in judged_graph(graph, [system]).nodes if n.fqn == "/player")
    assert {"/sim_camera/color_image", "/sim_camera/color_image/raw"} <= {e.name for e in launched.entities}


CLI_FILES = {
    "ros2hw/package.xml": PACKAGE_XML.format(name="ros2hw", build="ament_python"),
    "ros2hw/setup.py": """
        from setuptools import find_packages, setup

        setup(
            name='ros2hw',
            packages=find_packages(),
            entry_points={
                'ros2cli.command': ['hw = ros2hw.command.hw:HwCommand'],
                'ros2hw.verb': ['status = ros2hw.verb.status:StatusVerb'],
            },
        )
    """,
    "ros2hw/ros2hw/__init__.py": "",
    "ros2hw/ros2hw/verb/__init__.py": "",
    "ros2hw/ros2hw/verb/status.py": """
        from diagnostic_msgs.msg import DiagnosticArray
        import rclpy
        from ros2cli.node.strategy import NodeStrategy
        from ros2cli.verb import VerbExtension


        class StatusVerb(VerbExtension):
            '''Print the hardware status.'''

            def main(self, *, args):
                with NodeStrategy(args).direct_node as node:
                    node.create_subscription(DiagnosticArray, '/hardware/status', print, 10)
                    rclpy.spin_once(node)
    """,
}


def test_the_direct_node_of_a_node_strategy_is_a_node(tmp_path: Path) -> None:
    """``with NodeStrategy(args).direct_node as node:`` in a ros2cli verb subscribes on the
    strategy's DirectNode (ros2controlcli's view_hardware_status: not in the graph before)."""
    root = write(tmp_path, CLI_FILES)
    assert [e for node in entities(root).values() for e in node] == [
        ("subscriptions", "/hardware/status")]
    graph, analyses = analyse(root)
    [strategy] = [e for e in explain(analyses, graph).explanations if e.site.call == "NodeStrategy"]
    assert strategy.status == "unknown" and strategy.reasons[-1] == (
        "`node_name` is not passed: ros2cli.node.strategy.NodeStrategy.__init__ chooses the name "
        "when it runs")


# -- names read from a list parameter ------------------------------------------------------------------
EXECUTOR_FILES = {
    "arm_bringup/package.xml": PACKAGE_XML.format(name="arm_bringup", build="ament_python"),
    "arm_bringup/setup.py": setup_py("arm_bringup", "'executor = arm_bringup.executor:main', "
                                                   "'cameras = arm_bringup.executor:cameras'"),
    "arm_bringup/arm_bringup/__init__.py": "",
    "arm_bringup/arm_bringup/executor.py": """
        import rclpy
        from rclpy.node import Node
        from sensor_msgs.msg import JointState

        SENSORS = ['wrist_camera', 'base_camera']


        class StepExecutor(Node):
            def __init__(self):
                super().__init__('step_executor')
                self.declare_parameter('step_names', [''])
                self.declare_parameter('state_topics', ['joint_states'])
                steps = self.get_parameter('step_names').get_parameter_value().string_array_value
                for step in steps:
                    self.declare_parameter(step, [0.0] * 6)
                for topic in self.get_parameter('state_topics').value:
                    self.create_subscription(JointState, topic, self.on_state, 10)

            def on_state(self, msg):
                pass


        class CameraSwitch(Node):
            def __init__(self):
                super().__init__('camera_switch')
                for sensor in SENSORS:
                    self.declare_parameter(sensor + '.enabled', True)


        def main():
            rclpy.init()
            rclpy.spin(StepExecutor())


        def cameras():
            rclpy.init()
            rclpy.spin(CameraSwitch())
    """,
    "arm_bringup/config/steps.yaml": """
        step_executor:
          ros__parameters:
            step_names: ['home', 'grasp']
            home: [0.0, 0.0, 0.0, 0.0, 0.0, 0.0]
            grasp: [0.1, 0.2, 0.3, 0.0, 0.0, 0.0]
        camera_switch:
          ros__parameters:
            wrist_camera.enabled: false
            base_camera.enable: true
    """,
    "arm_bringup/launch/arm.launch.py": """
        import os

        from ament_index_python.packages import get_package_share_directory
        from launch import LaunchDescription
        from launch_ros.actions import Node


        def generate_launch_description():
            config = os.path.join(get_package_share_directory('arm_bringup'), 'config', 'steps.yaml')
            return LaunchDescription([
                Node(package='arm_bringup', executable='executor', name='step_executor',
                     parameters=[config]),
                Node(package='arm_bringup', executable='cameras', name='camera_switch',
                     parameters=[config]),
            ])
    """,
}


def test_names_from_a_list_parameter_are_its_default_and_unknown_others(tmp_path: Path) -> None:
    """``for step in <the 'step_names' parameter>: declare_parameter(step, …)``: the list comes
    from outside, so the steps a parameter file sets (``home``, ``grasp``) may be declared and
    are no unknown parameters (open_manipulator: 13 false ROS204); a subscription per listed
    topic keeps the default's topic and says the list may hold others. A constant list in
    code still decides its names: another node's misspelt ``base_camera.enable`` is reported."""
    root = write(tmp_path, EXECUTOR_FILES)
    assert entities(root) == {"/camera_switch": [],
                              "/step_executor": [("subscriptions", "/joint_states"),
                                                 ("subscriptions", "?")]}
    assert [(code, line) for code, _, line, _ in findings(root, ["ROS204"])] == [("ROS204", 9)]


def test_an_xml_parameter_value_with_substitutions_is_what_launch_makes_of_it(tmp_path: Path) -> None:
    """``<param name="image_topic" value="$(var image_topic)"/>`` in an XML launch file gets the
    argument's value (an including file's, or its default): the topic is named by it. An
    argument with no value anywhere leaves the name unknown, never the text ``$(var …)``
    (industrial_reconstruction: 6 false ROS006 on ``'$(var depth_image_topic)'``)."""
    files = {k: v for k, v in PLAYER_FILES.items() if not k.endswith(".launch.py")}
    files["archive_player/launch/player.launch.xml"] = """
        <launch>
          <arg name="image_topic"/>
          <node pkg="archive_player" exec="player" name="player">
            <param name="image_topic" value="$(var image_topic)"/>
          </node>
        </launch>
    """
    files["archive_player/launch/sim.launch.xml"] = """
        <launch>
          <arg name="image_topic" default="/sim_camera/color_image"/>
          <include file="$(find-pkg-share archive_player)/launch/player.launch.xml">
            <arg name="image_topic" value="$(var image_topic)"/>
          </include>
        </launch>
    """
    graph = build_graph(write(tmp_path, files))
    named_in = {}
    for system in graph.systems:
        launched = next(n for n in judged_graph(graph, [system]).nodes if n.fqn == "/player")
        named_in[system.launch_file.rpartition("/")[2]] = sorted(
            (e.name for e in launched.entities if e.kind == "publishers"), key=repr)
    assert named_in == {"player.launch.xml": [None, None],
                        "sim.launch.xml": ["/sim_camera/color_image", "/sim_camera/color_image/raw"]}
    assert findings(tmp_path, ["ROS006"]) == []


# -- pytest test classes ------------------------------------------------------------------------------
def _gc_package(name: str, msg: str) -> dict[str, str]:
    return {
        f"{name}/package.xml": PACKAGE_XML.format(name=name, build="ament_python"),
        f"{name}/setup.py": setup_py(name, f"'{name} = {name}.bridge:main'"),
        f"{name}/{name}/__init__.py": "",
        f"{name}/{name}/bridge.py": f"""
            import rclpy
            from rclpy.node import Node
            from gc_interfaces.msg import {msg}


            class Bridge(Node):
                def __init__(self):
                    super().__init__('gc_bridge')
                    self.pub = self.create_publisher({msg}, 'gc/data', 10)


            def main():
                rclpy.init()
                rclpy.spin(Bridge())
        """,
    }


GC_FILES = {
    **_gc_package("gc_bridge", "RCGCD15"),
    **_gc_package("gc_bridge_2022", "RCGCD14"),
    "gc_bridge/test/test_bridge.py": """
        import rclpy
        from rclpy.node import Node
        from gc_interfaces.msg import RCGCD15

        from gc_bridge.bridge import Bridge


        class TestBridge:
            received = []

            @classmethod
            def setup_class(cls):
                rclpy.init()

            @staticmethod
            def test_receiving():
                probe = Node('gc_probe')
                probe.create_subscription(RCGCD15, 'gc/data', TestBridge.received.append, 10)
                bridge = Bridge()
                rclpy.spin_once(bridge, timeout_sec=0.1)

            def test_status(self):
                node = Node('status_probe')
                node.create_publisher(RCGCD15, 'gc/status', 1)
    """,
}


def test_pytest_test_classes_are_run(tmp_path: Path) -> None:
    """pytest instantiates each ``Test…`` class of a test module and runs its ``test*``
    methods (static ones too) after ``setup_class``: their probes are in the graph
    (game_controller_spl: 12 sites, pyrobosim: 11 sites never reached before). A probe
    is a fixture: it is compared with its own package's ends only, so the other
    package's bridge with another message type is no mismatch of the test's."""
    root = write(tmp_path, GC_FILES)
    got = entities(root, ("publishers", "subscriptions"))
    assert got["/gc_probe"] == [("subscriptions", "/gc/data")]
    assert got["/status_probe"] == [("publishers", "/gc/status")]
    assert [path for _, path, _, _ in findings(root, ["ROS004"])] == ["gc_bridge/gc_bridge/bridge.py"]


def test_a_test_class_with_an_init_is_not_collected(tmp_path: Path) -> None:
    """pytest does not collect a ``Test…`` class that defines ``__init__``, nor a class of a
    module that is no test module: neither runs."""
    files = dict(GC_FILES)
    files["gc_bridge/test/test_bridge.py"] = GC_FILES["gc_bridge/test/test_bridge.py"].replace(
        "            received = []\n", "            def __init__(self):\n                self.received = []\n")
    files["gc_bridge/gc_bridge/probes.py"] = """
        from rclpy.node import Node


        class TestProbe:
            def test_probe(self):
                Node('library_probe')
    """
    got = entities(write(tmp_path, files), ("publishers", "subscriptions"))
    assert "/gc_probe" not in got and "/status_probe" not in got and "/library_probe" not in got


# -- pytest's built-in request fixture ------------------------------------------------------------------
REQUEST_FILES = {
    "chat_api/package.xml": PACKAGE_XML.format(name="chat_api", build="ament_python"),
    "chat_api/setup.py": setup_py("chat_api", ""),
    "chat_api/chat_api/__init__.py": "",
    "chat_api/chat_api/api.py": """
        from std_msgs.msg import String


        class TopicAPI:
            def __init__(self, node):
                self.node = node

            def publish(self, topic, text):
                pub = self.node.create_publisher(String, topic, 10)
                pub.publish(String(data=text))
    """,
    "chat_api/test/conftest.py": """
        import pytest
        import rclpy


        @pytest.fixture
        def ros():
            rclpy.init()
            yield
            rclpy.shutdown()
    """,
    "chat_api/test/test_api.py": """
        import pytest
        from rclpy.node import Node

        from chat_api.api import TopicAPI


        def test_single_publish(ros, request):
            node = Node(f'{request.node.originalname}_node')
            TopicAPI(node).publish(f'{request.node.name}_topic', 'hello')


        @pytest.mark.parametrize('text', ['a', 'b'])
        def test_parametrized_publish(ros, request, text):
            node = Node(f'{request.node.originalname}_node')
            TopicAPI(node).publish(f'{request.node.name}_topic', text)
    """,
}


def test_pytest_request_names_the_test(tmp_path: Path) -> None:
    """``request.node.originalname`` in a test function is the test's name, and so is
    ``request.node.name`` unless ``parametrize`` appends the parameters' ids, which the
    analysis does not spell (rai's API tests: 24 nodes of unknown name before)."""
    assert entities(write(tmp_path, REQUEST_FILES), ("publishers",)) == {
        "/test_parametrized_publish_node": [("publishers", "?")],
        "/test_single_publish_node": [("publishers", "/test_single_publish_topic")]}


def test_a_fixtures_request_is_not_one_tests(tmp_path: Path) -> None:
    """A fixture's ``request`` belongs to whichever test asks for it: a node the fixture names
    after ``request.node.name`` has an unknown name, not the fixture's own."""
    files = dict(REQUEST_FILES)
    files["chat_api/test/conftest.py"] = REQUEST_FILES["chat_api/test/conftest.py"] + """

        @pytest.fixture
        def probe(ros, request):
            from rclpy.node import Node
            return Node(f'{request.node.name}_probe')
    """
    files["chat_api/test/test_api.py"] = REQUEST_FILES["chat_api/test/test_api.py"] + """

        def test_probe(probe):
            TopicAPI(probe).publish('probe_topic', 'hello')
    """
    got = entities(write(tmp_path, files), ("publishers",))
    assert got[None] == [("publishers", "/probe_topic")]
    assert "/probe_probe" not in got and "/test_probe_probe" not in got
