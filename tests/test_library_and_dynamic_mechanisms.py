"""Extraction through library models (functools.partial, ros2param, rclpy's time source,
``rclpy.init`` arguments) and dynamic but common Python, on realistic multi-file packages:
each mechanism finds what the code creates, and the near-identical code where following
it must not invent a name or an entity."""
from __future__ import annotations

from pathlib import Path

from flake8_rosgraph.analysis import analyse, build_graph
from flake8_rosgraph.explain import explain

from test_workspace_discovery import PACKAGE_XML, write


def entities(root: Path, kinds: tuple[str, ...] = ("publishers", "subscriptions", "clients")
             ) -> dict[str | None, list[tuple]]:
    """Each node's entities of ``kinds`` as ``(kind, name or "?", type, callback)``."""
    return {node.fqn: sorted((e.kind, e.name or "?", e.type, e.callback) for e in node.entities
                             if e.kind in kinds)
            for node in build_graph(root).nodes}


def _package(name: str, modules: dict[str, str]) -> dict[str, str]:
    files = {f"{name}/package.xml": PACKAGE_XML.format(name=name, build="ament_python"),
             f"{name}/{name}/__init__.py": ""}
    files.update({f"{name}/{name}/{module}.py": text for module, text in modules.items()})
    return files


# -- functools.partial, lambdas -------------------------------------------------------------
PARTIAL_HANDLERS = """
    from std_msgs.msg import String


    class Relays:
        '''Mixin: one echo publisher per side, created when the side's first message arrives.'''

        def on_side(self, side, msg, suffix='echo'):
            self.create_publisher(String, f'{side}/{suffix}', 10)

        def on_tick(self, topic, *, depth=1):
            self.create_publisher(String, topic, depth)
"""

PARTIAL_NODE = """
    import functools
    import sys

    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import String

    from relays.handlers import Relays

    SIDES = ['left', 'right']


    class Relay(Relays, Node):
        def __init__(self):
            super().__init__('relay')
            for side in SIDES:
                self.create_subscription(String, side + '/in',
                                         functools.partial(self.on_side, side), 10)
            self.create_timer(1.0, functools.partial(self.on_tick, topic='heartbeat'))
            self.create_timer(2.0, lambda: self.on_tick('lambda_beat'))
            announce = functools.partial(self.on_side, suffix='ready')
            announce('status', None)


    def main():
        rclpy.init()
        rclpy.spin(Relay())
"""


def test_partial_keeps_its_bound_arguments_for_callbacks_and_calls(tmp_path: Path) -> None:
    """A subscription callback bound to each side of a loop publishes that side's echo; a
    timer partial with a keyword, a lambda timer and a partial called directly keep theirs."""
    root = write(tmp_path, _package("relays", {"handlers": PARTIAL_HANDLERS, "relay": PARTIAL_NODE}))
    assert entities(root) == {"/relay": [
        ("publishers", "/heartbeat", "std_msgs/msg/String", None),
        ("publishers", "/lambda_beat", "std_msgs/msg/String", None),
        ("publishers", "/left/echo", "std_msgs/msg/String", None),
        ("publishers", "/right/echo", "std_msgs/msg/String", None),
        ("publishers", "/status/ready", "std_msgs/msg/String", None),
        ("subscriptions", "/left/in", "std_msgs/msg/String", "Relays.on_side"),
        ("subscriptions", "/right/in", "std_msgs/msg/String", "Relays.on_side"),
    ]}


def test_partial_with_unknown_bound_arguments_names_nothing(tmp_path: Path) -> None:
    """The same node with the side read from the command line, and bound through ``*args``
    of unknown length: the echo topics are unknown, never a default or a shifted argument."""
    node = PARTIAL_NODE.replace("for side in SIDES:", "for side in sys.argv[1:]:").replace(
        "functools.partial(self.on_tick, topic='heartbeat')",
        "functools.partial(self.on_tick, *sys.argv)")
    root = write(tmp_path, _package("relays", {"handlers": PARTIAL_HANDLERS, "relay": node}))
    assert entities(root) == {"/relay": [
        ("publishers", "/lambda_beat", "std_msgs/msg/String", None),
        ("publishers", "/status/ready", "std_msgs/msg/String", None),
        ("publishers", "?", "std_msgs/msg/String", None),
        ("publishers", "?", "std_msgs/msg/String", None),
        ("subscriptions", "?", "std_msgs/msg/String", "Relays.on_side"),
    ]}


# -- nodes named by their callers, threads -------------------------------------------------
FACTORY_PACKAGE = _package("fleet", {
    "factory": """
        import rclpy
        from rclpy.node import Node
        from std_msgs.msg import String


        def make_pair(name):
            plain = Node(name)
            plain.create_publisher(String, 'state', 1)
            made = rclpy.create_node(name + '_monitor', namespace='fleet')
            made.create_subscription(String, 'state', lambda msg: None, 1)
            return plain, made
    """,
    "worker": """
        from rclpy.node import Node
        from std_msgs.msg import String


        class Worker(Node):
            def __init__(self, name='worker_default'):
                super().__init__(name)
                self.create_publisher(String, 'progress', 1)
    """,
    "main": """
        import threading

        import rclpy

        from fleet.factory import make_pair
        from fleet.worker import Worker


        def main():
            rclpy.init()
            make_pair('scout')
            threading.Thread(target=lambda: Worker('digger')).start()
            rclpy.spin(Worker())
    """,
})


def test_nodes_named_by_arguments_get_their_callers_names(tmp_path: Path) -> None:
    """``Node(name)`` and ``rclpy.create_node(name + …)`` in a helper ``main`` calls are
    the names ``main`` passes, with no extra unknown-named node from analysing the helper on
    its own first; a node built in a thread's lambda has the name the lambda passes."""
    got = entities(write(tmp_path, FACTORY_PACKAGE))
    assert got == {
        "/digger": [("publishers", "/progress", "std_msgs/msg/String", None)],
        "/fleet/scout_monitor": [("subscriptions", "/fleet/state", "std_msgs/msg/String",
                                  "make_pair.<lambda>")],
        "/scout": [("publishers", "/state", "std_msgs/msg/String", None)],
        "/worker_default": [("publishers", "/progress", "std_msgs/msg/String", None)],
    }


def test_a_thread_lambda_with_unknown_arguments_does_not_use_the_defaults(tmp_path: Path) -> None:
    """The worker of the thread is named from the command line: its node is unknown-named,
    not ``worker_default`` (which only the node spun by ``main`` really is)."""
    files = dict(FACTORY_PACKAGE)
    files["fleet/fleet/main.py"] = files["fleet/fleet/main.py"].replace(
        "Worker('digger')", "Worker(sys.argv[1])").replace(
        "import threading", "import sys\n        import threading")
    got = entities(write(tmp_path, files))
    assert sorted(got, key=str) == ["/fleet/scout_monitor", "/scout", "/worker_default", None]
    (unnamed,) = [n for n in build_graph(tmp_path).nodes if n.fqn is None]
    assert unnamed.cls == "Worker"


# -- rclpy.init(args=...) ----------------------------------------------------------------------
ROBOT_PACKAGE = _package("robot", {
    "base": """
        from rclpy.node import Node
        from geometry_msgs.msg import Twist


        class Base(Node):
            def __init__(self, **kwargs):
                super().__init__('base', **kwargs)
                self.create_publisher(Twist, 'cmd', 10)
                self.create_publisher(Twist, '/diag/cmd', 10)
    """,
    "bringup": """
        import rclpy
        from std_msgs.msg import String

        from robot.base import Base

        ROS_ARGS = ['--ros-args', '-r', '__ns:=/robot', '-r', 'cmd:=cmd_vel', '-p', 'rate:=5']


        def main():
            rclpy.init(args=ROS_ARGS)
            Base()
            local = rclpy.create_node('local', cli_args=['--ros-args', '-r', 'cmd:=local_cmd'])
            local.create_publisher(String, 'cmd', 1)
            Base(use_global_arguments=False, namespace='isolated')
    """,
    "sim": """
        import rclpy

        from robot.base import Base


        def main():
            rclpy.init()
            Base(namespace='sim')
    """,
})


def test_init_arguments_apply_to_the_nodes_of_their_process(tmp_path: Path) -> None:
    """``rclpy.init(args=[…])`` moves the nodes its entry point creates to ``/robot`` and
    remaps ``cmd``; a node's own ``cli_args`` rule wins, ``use_global_arguments=False`` opts
    out, and the other entry point's node (plain ``rclpy.init()``) is untouched."""
    got = {fqn: [name for _, name, _, _ in ents]
           for fqn, ents in entities(write(tmp_path, ROBOT_PACKAGE), ("publishers",)).items()}
    assert got == {
        "/isolated/base": ["/diag/cmd", "/isolated/cmd"],
        "/robot/base": ["/diag/cmd", "/robot/cmd_vel"],
        "/robot/local": ["/robot/local_cmd"],
        "/sim/base": ["/diag/cmd", "/sim/cmd"],
    }


def test_init_arguments_disagreeing_on_a_shared_node_apply_to_neither(tmp_path: Path) -> None:
    """Both entry points build their node through one helper; their inits disagree, so the
    node made there keeps its own names rather than one process's (or both)."""
    files = dict(ROBOT_PACKAGE)
    files["robot/robot/start.py"] = """
        from robot.base import Base


        def start():
            return Base()
    """
    files["robot/robot/bringup.py"] = """
        import rclpy

        from robot.start import start


        def main():
            rclpy.init(args=['--ros-args', '-r', '__ns:=/robot'])
            start()
    """
    files["robot/robot/sim.py"] = """
        import rclpy

        from robot.start import start


        def main():
            rclpy.init(args=['--ros-args', '-r', '__ns:=/sim'])
            start()
    """
    assert sorted(entities(write(tmp_path, files), ("publishers",))) == ["/base"]


# -- library models: parameter clients, message_filters, the /clock subscription -------------
TUNER_PACKAGE = _package("tuner", {
    "remote": """
        from ros2param.api import call_describe_parameters, call_get_parameters
        from ros2param.api import call_list_parameters, call_set_parameters

        TARGETS = ('camera', '/arm/controller')


        def snapshot(node, target):
            names = call_list_parameters(node=node, node_name=target)
            call_describe_parameters(node=node, node_name=target, parameter_names=names)
            return call_get_parameters(node=node, node_name=target, parameter_names=names)


        def restore(node, target, parameters):
            call_set_parameters(node=node, node_name=target, parameters=parameters)
    """,
    "tuner": """
        import rclpy
        from rclpy.node import Node
        from rclpy.parameter import Parameter
        from rclpy.parameter_client import AsyncParameterClient
        import message_filters
        from sensor_msgs.msg import CameraInfo, Image

        from tuner.remote import TARGETS, restore, snapshot


        class Tuner(Node):
            def __init__(self):
                super().__init__('tuner', parameter_overrides=[
                    Parameter('use_sim_time', Parameter.Type.BOOL, True)])
                self.lidar = AsyncParameterClient(self, remote_node_name='lidar')
                image = message_filters.Subscriber(self, Image, 'image')
                info = message_filters.Subscriber(node=self, msg_type=CameraInfo, topic='camera_info')
                sync = message_filters.ApproximateTimeSynchronizer([image, info], 10, 0.05)
                sync.registerCallback(self.on_pair)

            def on_pair(self, image, info):
                self.create_publisher(Image, 'rectified', 1)


        def main():
            rclpy.init()
            node = Tuner()
            for target in TARGETS:
                restore(node, target, snapshot(node, target))
            rclpy.spin(node)
    """,
})


def test_library_models_of_parameter_clients_filters_and_sim_time(tmp_path: Path) -> None:
    """ros2param's helpers make the node a client of the remote node's parameter service
    (with its rcl_interfaces type); AsyncParameterClient makes all six; message_filters
    subscribers take keywords and the synchronizer runs its two-message callback; a node
    whose overrides set ``use_sim_time`` subscribes to ``/clock``."""
    (tuner,) = build_graph(write(tmp_path, TUNER_PACKAGE)).nodes
    got = sorted((e.kind, e.name, e.type, e.via) for e in tuner.entities if e.kind != "parameters")
    lidar = [("clients", f"/lidar/{srv}", f"rcl_interfaces/srv/{kind}",
              "rclpy.parameter_client.AsyncParameterClient")
             for srv, kind in [("describe_parameters", "DescribeParameters"),
                               ("get_parameter_types", "GetParameterTypes"),
                               ("get_parameters", "GetParameters"),
                               ("list_parameters", "ListParameters"),
                               ("set_parameters", "SetParameters"),
                               ("set_parameters_atomically", "SetParametersAtomically")]]
    helpers = [("clients", f"{target}/{srv}", f"rcl_interfaces/srv/{kind}", f"ros2param.api.call_{srv}")
               for target in ("/arm/controller", "/camera")
               for srv, kind in [("describe_parameters", "DescribeParameters"),
                                 ("get_parameters", "GetParameters"),
                                 ("list_parameters", "ListParameters"),
                                 ("set_parameters", "SetParameters")]]
    assert got == sorted(lidar + helpers + [
        ("publishers", "/rectified", "sensor_msgs/msg/Image", None),
        ("subscriptions", "/camera_info", "sensor_msgs/msg/CameraInfo", "message_filters.Subscriber"),
        ("subscriptions", "/clock", "rosgraph_msgs/msg/Clock", "rclpy.time_source.TimeSource"),
        ("subscriptions", "/image", "sensor_msgs/msg/Image", "message_filters.Subscriber"),
    ])
    clock = next(e for e in tuner.entities if e.name == "/clock")
    assert clock.qos["depth"] == 1 and clock.qos["reliability"] == "best_effort"


def test_unknown_targets_and_switches_invent_nothing(tmp_path: Path) -> None:
    """The targets come from the command line and ``use_sim_time`` from a declared parameter
    (an overridable default) or is false: the helpers' clients are unknown-named, there is no
    ``/clock`` subscription, and explain does not list the switched-off one as missing."""
    files = dict(TUNER_PACKAGE)
    files["tuner/tuner/remote.py"] = files["tuner/tuner/remote.py"].replace(
        "TARGETS = ('camera', '/arm/controller')", "import sys\n        TARGETS = sys.argv[1:]")
    files["tuner/tuner/tuner.py"] = files["tuner/tuner/tuner.py"].replace(
        "Parameter('use_sim_time', Parameter.Type.BOOL, True)",
        "Parameter('use_sim_time', Parameter.Type.BOOL, False)")
    files["tuner/tuner/sim.py"] = """
        import rclpy
        from rclpy.parameter import Parameter


        def main():
            rclpy.init()
            probe = rclpy.create_node('probe')
            sim = probe.declare_parameter('sim', True).value
            rclpy.create_node('follower', parameter_overrides=[Parameter('use_sim_time', value=sim)])
    """
    root = write(tmp_path, files)
    graph, analysis = analyse(root)
    by_node = {n.fqn: sorted((e.kind, e.name or "?") for e in n.entities if e.kind != "parameters")
               for n in graph.nodes}
    assert by_node["/follower"] == [] and by_node["/probe"] == []
    tuner = by_node["/tuner"]
    assert ("subscriptions", "/clock") not in tuner
    assert [name for kind, name in tuner if kind == "clients" and not name.startswith("/lidar/")] \
        == ["?"] * 4
    missing = [e for e in explain(analysis, graph).explanations if e.status == "missing"]
    assert missing == []


# -- dynamic Python ----------------------------------------------------------------------------
def test_getattr_on_an_unknown_object_is_unknown_not_its_default(tmp_path: Path) -> None:
    """``getattr(config, 'topic', 'scan')`` on a configuration object the analysis cannot see
    may be any topic: the default is only one possibility (a partly known name beside the
    unknown), never the name; on the node itself, which nothing gives that attribute, it is
    the default."""
    root = write(tmp_path, _package("lidar", {"driver": """
        import rclpy
        from rclpy.node import Node
        from sensor_msgs.msg import LaserScan

        from vendor_sdk import load_config


        class Driver(Node):
            def __init__(self):
                super(Driver, self).__init__('driver')
                config = load_config()
                self.create_publisher(LaserScan, getattr(config, 'topic', 'scan'), 10)
                self.create_publisher(LaserScan, getattr(self, 'debug_topic', 'scan_debug'), 1)


        def main():
            rclpy.init()
            rclpy.spin(Driver())
    """}))
    assert entities(root) == {"/driver": [("publishers", "/scan", "sensor_msgs/msg/LaserScan", None),
                                          ("publishers", "/scan_debug", "sensor_msgs/msg/LaserScan", None),
                                          ("publishers", "?", "sensor_msgs/msg/LaserScan", None)]}
    partial = {e.name: e.partial for node in build_graph(root).nodes for e in node.entities
               if e.kind == "publishers"}
    assert partial == {"/scan": True, "/scan_debug": False, None: False}
