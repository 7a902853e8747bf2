"""Values real nodes compute their names with, found on a fifth round of repositories
outside every test set: ``dict.get`` of a key the dict lists, ``os.path.join``, a dataclass
field's ``default_factory``, and the parts of a ``match`` subject a ``case`` captures. Each
on a realistic multi-file workspace, with a twin where following the code must not invent a
name or an entity."""
from __future__ import annotations

from pathlib import Path

from test_recall_globals_and_escapes import package
from test_recall_mechanisms import entities
from test_workspace_discovery import write

PUBLISHERS = ("publishers",)


def _workspace(tmp_path: Path, node: str, config: str) -> Path:
    """A package ``camera_tools`` whose ``relay`` node reads its names from ``config``."""
    return write(tmp_path, package("camera_tools", "'relay = camera_tools.relay:main'",
                                    {"config": config, "relay": node}))


# -- dict.get of a key the dict lists ------------------------------------------------------
TOPICS = """
    TOPICS = {'image': 'camera/image_raw', 'info': 'camera/camera_info'}
"""
GET_NODE = """
    import rclpy
    from rclpy.node import Node
    from sensor_msgs.msg import CameraInfo, Image

    from camera_tools.config import TOPICS


    class Relay(Node):
        def __init__(self):
            super().__init__('relay')
            self.create_publisher(Image, TOPICS.get('image', 'image'), 10)
            self.create_publisher(CameraInfo, TOPICS.get('depth_info', 'depth/camera_info'), 10)


    def main():
        rclpy.init()
        rclpy.spin(Relay())
"""


def test_get_of_a_listed_key_is_never_the_default(tmp_path: Path) -> None:
    """``TOPICS.get('image', 'image')`` finds the key the literal lists: only its value is
    the topic, not the default beside it (a second, invented publisher before); a key the
    dict lacks gives the default."""
    root = _workspace(tmp_path, GET_NODE, TOPICS)
    assert entities(root, PUBLISHERS) == {
        "/relay": [("publishers", "/camera/image_raw"), ("publishers", "/depth/camera_info")]}


def test_get_of_a_key_a_caller_may_add_keeps_both(tmp_path: Path) -> None:
    """The twin: a dict with a key the analysis does not know may hold the key looked up, so
    both the found value and the default stay possible."""
    config = "import os\nTOPICS = {'image': 'camera/image_raw', os.environ['EXTRA']: 'x'}\n"
    root = _workspace(tmp_path, GET_NODE, config)
    names = [name for _, name in entities(root, PUBLISHERS)["/relay"]]
    assert "/image" in names and "/camera/image_raw" in names


# -- os.path.join ----------------------------------------------------------------------------
JOIN_NODE = """
    import os

    import rclpy
    from rclpy.node import Node
    from sensor_msgs.msg import Image

    from camera_tools.config import PREFIX


    def main():
        rclpy.init()
        node = Node('relay')
        node.create_publisher(Image, os.path.join(PREFIX, 'image_raw'), 10)
        node.create_publisher(Image, os.path.join(PREFIX, os.environ['STREAM']), 10)
        rclpy.spin(node)
"""


def test_os_path_join_of_known_parts_is_the_name(tmp_path: Path) -> None:
    """``os.path.join('front_camera', 'image_raw')`` folds like Python's POSIX join; with an
    unknown part the name stays unknown rather than a guess."""
    root = _workspace(tmp_path, JOIN_NODE, "PREFIX = 'front_camera'\n")
    assert entities(root, PUBLISHERS) == {
        "/relay": [("publishers", "/front_camera/image_raw"), ("publishers", "?")]}


def test_os_path_join_with_an_absolute_part_starts_again(tmp_path: Path) -> None:
    """The twin: an absolute second part replaces the first, as in Python."""
    root = _workspace(tmp_path, JOIN_NODE.replace("'image_raw'", "'/image_raw'"),
                      "PREFIX = 'front_camera'\n")
    assert ("publishers", "/image_raw") in entities(root, PUBLISHERS)["/relay"]


# -- a dataclass field's default_factory -----------------------------------------------------
FIELDS = """
    from dataclasses import dataclass, field


    @dataclass
    class RelayConfig:
        cameras: list = field(default_factory=lambda: ['front', 'rear'])
        suffix: str = field(default='image_raw')
        extra: list = field(default_factory=list)
"""
FIELDS_NODE = """
    import rclpy
    from rclpy.node import Node
    from sensor_msgs.msg import Image

    from camera_tools.config import RelayConfig


    class Relay(Node):
        def __init__(self, config: RelayConfig):
            super().__init__('relay')
            for camera in config.cameras:
                self.create_publisher(Image, f'{camera}/{config.suffix}', 10)
            for topic in config.extra:
                self.create_publisher(Image, topic, 10)


    def main():
        rclpy.init()
        rclpy.spin(Relay(RelayConfig()))
"""


def test_a_default_factory_gives_the_field_its_default(tmp_path: Path) -> None:
    """``field(default_factory=lambda: [...])`` is the list it returns, ``field(default=…)``
    its value; ``field(default_factory=list)`` an empty list that code the analysis does not
    see may fill, so the loop over it names nothing it would guess."""
    root = _workspace(tmp_path, FIELDS_NODE, FIELDS)
    assert entities(root, PUBLISHERS) == {"/relay": [
        ("publishers", "/front/image_raw"), ("publishers", "/rear/image_raw"),
        ("publishers", "?")]}


def test_a_field_given_by_the_caller_is_not_its_default(tmp_path: Path) -> None:
    """The twin: the caller passes the cameras, so the factory's list names nothing."""
    root = _workspace(tmp_path, FIELDS_NODE.replace("RelayConfig()", "RelayConfig(['left'])"),
                      FIELDS)
    assert ("publishers", "/left/image_raw") in entities(root, PUBLISHERS)["/relay"]
    assert ("publishers", "/front/image_raw") not in entities(root, PUBLISHERS)["/relay"]


# -- what a ``case`` captures ------------------------------------------------------------------
STREAMS = """
    from dataclasses import dataclass


    @dataclass
    class ImageStream:
        topic: str


    @dataclass
    class InfoStream:
        topic: str
"""
MATCH_NODE = """
    import rclpy
    from rclpy.node import Node
    from sensor_msgs.msg import CameraInfo, Image

    from camera_tools.config import ImageStream, InfoStream


    class Relay(Node):
        def __init__(self, streams):
            super().__init__('relay')
            for stream in streams:
                match stream:
                    case ImageStream(topic=name):
                        self.create_publisher(Image, name, 10)
                    case InfoStream(topic=name):
                        self.create_publisher(CameraInfo, name, 10)
            match {'mode': 'rgb', 'topic': 'preview'}:
                case {'topic': preview}:
                    self.create_publisher(Image, preview, 10)


    def main():
        rclpy.init()
        rclpy.spin(Relay([ImageStream('image_raw'), InfoStream('camera_info')]))
"""


def _typed(root: Path) -> list[tuple[str, str]]:
    from flake8_rosgraph.analysis import build_graph
    [node] = build_graph(root).nodes
    return sorted((e.name or "?", e.type or "?") for e in node.entities if e.kind == "publishers")


def test_a_case_captures_the_attribute_and_item_it_matches(tmp_path: Path) -> None:
    """``case ImageStream(topic=name)`` binds the attribute of the streams that pattern can
    match (not the info stream's), ``case {'topic': preview}`` the dict's item."""
    root = _workspace(tmp_path, MATCH_NODE, STREAMS)
    assert _typed(root) == [("/camera_info", "sensor_msgs/msg/CameraInfo"),
                            ("/image_raw", "sensor_msgs/msg/Image"),
                            ("/preview", "sensor_msgs/msg/Image")]


def test_a_positional_class_pattern_captures_nothing_it_would_guess(tmp_path: Path) -> None:
    """The twin: ``case ImageStream(name)`` goes through ``__match_args__``, which the
    analysis does not follow: the name is unknown, never the other stream's."""
    text = MATCH_NODE.replace("ImageStream(topic=name)", "ImageStream(name)")
    root = _workspace(tmp_path, text, STREAMS)
    assert ("?", "sensor_msgs/msg/Image") in _typed(root)
    assert ("/camera_info", "sensor_msgs/msg/Image") not in _typed(root)
