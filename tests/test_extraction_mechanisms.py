"""Extraction mechanisms on realistic multi-file packages: each one follows what real code
does, and one case per mechanism where following it must not invent entities."""
from __future__ import annotations

from pathlib import Path

from flake8_rosgraph.analysis import build_graph

from test_workspace_discovery import PACKAGE_XML, write


def publishers(root: Path) -> dict[str | None, list[str]]:
    graph = build_graph(root)
    out: dict[str | None, list[str]] = {}
    for node in graph.nodes:
        out.setdefault(node.fqn, []).extend(
            sorted(e.name or "?" for e in node.entities if e.kind == "publishers"))
    return out


STAR_PACKAGE = {
    "fleet/package.xml": PACKAGE_XML.format(name="fleet", build="ament_python"),
    "fleet/fleet/__init__.py": """
        from .names import *
    """,
    "fleet/fleet/names.py": """
        __all__ = ['CMD_TOPIC', '_ODOM_TOPIC']
        CMD_TOPIC = 'cmd_vel'
        _ODOM_TOPIC = 'odom'
        STATUS_TOPIC = 'status_internal'
    """,
    "fleet/fleet/topics.py": """
        STATUS_TOPIC = 'status'
        from fleet import *
    """,
    "fleet/fleet/base.py": """
        import rclpy
        from rclpy.node import Node
        from std_msgs.msg import String

        from fleet import CMD_TOPIC, _ODOM_TOPIC
        from fleet.topics import STATUS_TOPIC


        class Base(Node):
            def __init__(self):
                super().__init__('base')
                self.create_publisher(String, CMD_TOPIC, 10)
                self.create_publisher(String, _ODOM_TOPIC, 10)
                self.create_publisher(String, STATUS_TOPIC, 10)


        def main():
            rclpy.init()
            rclpy.spin(Base())
    """,
}


def test_star_import_honours_all(tmp_path: Path) -> None:
    """``__all__`` exports a private name and hides a public one: ``STATUS_TOPIC`` of
    topics.py is not overwritten by the star import, so no second status topic appears."""
    assert publishers(write(tmp_path, STAR_PACKAGE)) == {
        "/base": ["/cmd_vel", "/odom", "/status"]}


def test_star_import_without_all_takes_public_names(tmp_path: Path) -> None:
    files = dict(STAR_PACKAGE)
    files["fleet/fleet/names.py"] = """
        CMD_TOPIC = 'cmd_vel'
        _ODOM_TOPIC = 'odom'
    """
    files["fleet/fleet/__init__.py"] = "from .names import *\nfrom .names import _ODOM_TOPIC\n"
    assert publishers(write(tmp_path, files)) == {"/base": ["/cmd_vel", "/odom", "/status"]}


CLI_PACKAGE = {
    "relay/package.xml": PACKAGE_XML.format(name="relay", build="ament_python"),
    "relay/relay/__init__.py": "",
    "relay/relay/args.py": """
        def ros_args(robot):
            return ['--ros-args', '-r', '__ns:=/' + robot, '-r', 'chatter:=talk',
                    '-p', 'rate:=5', '-r', 'other_node:odom:=wrong']
    """,
    "relay/relay/relay.py": """
        import rclpy
        from rclpy.node import Node
        from std_msgs.msg import String

        from relay.args import ros_args


        class Relay(Node):
            def __init__(self, robot):
                super().__init__('relay', cli_args=ros_args(robot))
                self.create_publisher(String, 'chatter', 10)
                self.create_publisher(String, 'odom', 10)
                self.create_publisher(String, '/abs/chatter', 10)


        def main():
            rclpy.init()
            renamed = rclpy.create_node('draft', cli_args=['--ros-args', '-r', '__node:=final'])
            renamed.create_publisher(String, '~/state', 1)
            plain = rclpy.create_node('plain', cli_args=['--', '-r', '__ns:=/ignored'])
            plain.create_publisher(String, 'chatter', 1)
            rclpy.spin(Relay('scout'))
    """,
}


def test_cli_args_namespace_name_and_remaps(tmp_path: Path) -> None:
    """``__ns``/``__node`` and topic rules of ``cli_args`` apply to their node only; a rule
    for another node and arguments outside ``--ros-args`` change nothing."""
    assert publishers(write(tmp_path, CLI_PACKAGE)) == {
        "/final": ["/final/state"],
        "/plain": ["/chatter"],
        "/scout/relay": ["/abs/chatter", "/scout/odom", "/scout/talk"],
    }


HANDLERS_PACKAGE = {
    "mux/package.xml": PACKAGE_XML.format(name="mux", build="ament_python"),
    "mux/mux/__init__.py": "",
    "mux/mux/table.py": """
        from std_msgs.msg import String
        from std_srvs.srv import Trigger

        SERVICES = {}
        SERVICES['reset'] = Trigger
        SERVICES.update({'stop': Trigger})
        OUTPUTS = []
        OUTPUTS.append(('left/cmd', String))
        OUTPUTS.extend([('right/cmd', String)])
    """,
    "mux/mux/mux.py": """
        import rclpy
        from rclpy.node import Node
        from std_msgs.msg import String

        from mux.table import OUTPUTS, SERVICES


        class Mux(Node):
            def __init__(self):
                super().__init__('mux')
                for topic, msg_type in OUTPUTS:
                    self.create_publisher(msg_type, topic, 10)
                for name, srv_type in SERVICES.items():
                    self.create_service(srv_type, name, self.on_call)
                inputs = []
                inputs.append('joy_in')
                if not inputs:
                    raise RuntimeError('no inputs configured')
                self.subs = [self.create_subscription(String, t, self.on_msg, 10) for t in inputs]
                match self.get_name():
                    case str() as me:
                        self.create_publisher(String, me + '_state', 1)
                if (extra := 'diagnostics'):
                    self.create_publisher(String, extra, 1)

            def on_call(self, request, response):
                return response

            def on_msg(self, msg):
                pass


        class Recorder(Node):
            def __init__(self):
                super().__init__('recorder')
                wanted = []
                wanted.append('rosout_copy')
                for topic in self.get_parameter('topics').value:
                    self.create_subscription(String, topic, self.on_msg, 10)
                for topic in wanted:
                    self.create_subscription(String, topic, self.on_msg, 10)

            def on_msg(self, msg):
                pass


        def main():
            rclpy.init()
            rclpy.spin(Mux())
            rclpy.spin(Recorder())
    """,
}


def test_loops_containers_and_patterns_inside_functions(tmp_path: Path) -> None:
    """Handler tables filled in one module and iterated in another, a list appended before
    ``if not lst: raise`` (the rest of the constructor stays reachable), comprehension, match
    and walrus bindings. Precision: each node gets only its own list's topics, and a loop over
    a run-time parameter stays one unknown subscription."""
    graph = build_graph(write(tmp_path, HANDLERS_PACKAGE))
    got = {node.fqn: sorted((e.kind, e.name or "?") for e in node.entities
                            if e.kind != "parameters") for node in graph.nodes}
    assert got == {
        "/mux": [("publishers", "/diagnostics"), ("publishers", "/left/cmd"),
                 ("publishers", "/mux_state"), ("publishers", "/right/cmd"),
                 ("services", "/reset"), ("services", "/stop"),
                 ("subscriptions", "/joy_in")],
        "/recorder": [("subscriptions", "/rosout_copy"), ("subscriptions", "?")],
    }


DYNAMIC_PACKAGE = {
    "cams/package.xml": PACKAGE_XML.format(name="cams", build="ament_python"),
    "cams/cams/__init__.py": "",
    "cams/cams/base.py": """
        from rclpy.node import Node
        from sensor_msgs.msg import Image


        class Camera(Node):
            TOPIC = 'image_raw'

            def __init__(self, name):
                super(Camera, self).__init__(name)
                self.create_publisher(Image, self.__class__.TOPIC, 10)
                type(self).add_info(self)
                suffix = getattr(self, 'info_suffix', 'camera_info')
                self.create_publisher(Image, suffix, 10)
                self.create_publisher(Image, getattr(self, 'mode_topic', 'mode'), 1)

            def add_info(self):
                self.create_publisher(Image, 'info_base', 1)
    """,
    "cams/cams/stereo.py": """
        import rclpy
        from sensor_msgs.msg import Image

        from cams.base import Camera


        class Stereo(Camera):
            TOPIC = 'stereo/image'

            def __init__(self):
                self.mode_topic = 'stereo/mode'
                super(Stereo, self).__init__('stereo')

            def add_info(self):
                self.create_publisher(Image, 'stereo/info', 1)


        def main():
            rclpy.init()
            rclpy.spin(Stereo())
    """,
}


def test_dynamic_class_access_and_getattr_defaults(tmp_path: Path) -> None:
    """``self.__class__``/``type(self)`` are the instance's own class (the subclass's
    attribute and override, not the base's), two-argument ``super`` reaches the base, and
    ``getattr`` with a default gives only the default when nothing can set the attribute;
    when some code assigns it, the heap cannot order the assignment and the read, so both
    stay possible (never the base's ``TOPIC`` or ``add_info``, never unknown)."""
    assert publishers(write(tmp_path, DYNAMIC_PACKAGE)) == {
        "/stereo": ["/camera_info", "/mode", "/stereo/image", "/stereo/info", "/stereo/mode"]}


def test_container_filled_by_a_helper_keeps_its_loop_alive(tmp_path: Path) -> None:
    """A dict filled through a helper it is passed to (an alias the analysis does not
    rebind) is not trusted to stay empty: the commands built in the loop over it stay in the
    graph, unknown-named, and the node's fixed subscription after ``if not commands: raise`` is
    kept."""
    root = write(tmp_path, {
        "pad/package.xml": PACKAGE_XML.format(name="pad", build="ament_python"),
        "pad/pad/__init__.py": "",
        "pad/pad/pad.py": """
            import rclpy
            from rclpy.node import Node
            from sensor_msgs.msg import Joy
            from std_msgs.msg import String


            def fill(table, key, value):
                head, _, rest = key.partition('.')
                table.setdefault(head, {})[rest] = value


            class Pad(Node):
                def __init__(self):
                    super().__init__('pad', allow_undeclared_parameters=True)
                    commands = {}
                    for name in sorted(self._parameters):
                        fill(commands, name, self.get_parameter(name).value)
                    if not commands:
                        raise RuntimeError('no commands configured')
                    for name, config in commands.items():
                        self.create_publisher(String, config['topic'], 1)
                    self.create_subscription(Joy, 'joy', self.on_joy, 1)

                def on_joy(self, msg):
                    pass


            def main():
                rclpy.init()
                rclpy.spin(Pad())
        """,
    })
    graph = build_graph(root)
    (node,) = graph.nodes
    assert sorted((e.kind, e.name or "?") for e in node.entities if e.kind != "parameters") == [
        ("publishers", "?"), ("subscriptions", "/joy")]


def test_library_models_wait_for_message_and_keyword_only_creation(tmp_path: Path) -> None:
    """``wait_for_message`` subscribes its node; every ``create_*`` spelled with keywords
    only is the same entity as the positional spelling."""
    root = write(tmp_path, {
        "probe/package.xml": PACKAGE_XML.format(name="probe", build="ament_python"),
        "probe/probe/__init__.py": "",
        "probe/probe/probe.py": """
            import rclpy
            from rclpy.wait_for_message import wait_for_message
            from rclpy.node import Node
            from std_msgs.msg import String
            from std_srvs.srv import Trigger


            class Probe(Node):
                def __init__(self):
                    super().__init__(node_name='probe', namespace='/lab')
                    self.create_publisher(msg_type=String, topic='out', qos_profile=10)
                    self.create_subscription(msg_type=String, topic='in', callback=self.on_msg,
                                             qos_profile=10)
                    self.create_service(srv_type=Trigger, srv_name='poke', callback=self.on_poke)
                    self.create_client(srv_type=Trigger, srv_name='peer/poke')
                    self.create_timer(timer_period_sec=0.5, callback=self.on_tick)

                def on_msg(self, msg):
                    pass

                def on_poke(self, request, response):
                    return response

                def on_tick(self):
                    pass


            def main():
                rclpy.init()
                node = Probe()
                ok, first = wait_for_message(String, node, '/lab/status', time_to_wait=2.0)
                rclpy.spin(node)
        """,
    })
    (node,) = build_graph(root).nodes
    got = sorted((e.kind, e.name, e.type, e.period) for e in node.entities
                 if e.kind != "parameters")
    assert got == [
        ("clients", "/lab/peer/poke", "std_srvs/srv/Trigger", None),
        ("publishers", "/lab/out", "std_msgs/msg/String", None),
        ("services", "/lab/poke", "std_srvs/srv/Trigger", None),
        ("subscriptions", "/lab/in", "std_msgs/msg/String", None),
        ("subscriptions", "/lab/status", "std_msgs/msg/String", None),
        ("timers", None, None, 0.5),
    ]


def _pattern_package(patterns: int) -> dict[str, str]:
    """A swarm package: a base node class with a gate that wraps callbacks in a closure, one
    module per behaviour (each its own message and topic), and one helper that inits, builds
    and spins whichever node class each executable's ``main`` passes it."""
    files = {
        "swarm/package.xml": PACKAGE_XML.format(name="swarm", build="ament_python"),
        "swarm/swarm/__init__.py": "",
        "swarm/swarm/spin.py": """
            import rclpy


            def init_and_spin(args, node_class):
                rclpy.init(args=args)
                rclpy.spin(node_class())
        """,
        "swarm/swarm/base.py": """
            from rclpy.node import Node


            class Behaviour(Node):
                def __init__(self, name):
                    super().__init__(name)
                    self.enabled = True

                def gated(self, callback):
                    def run():
                        if self.enabled:
                            callback()
                    return lambda: run()
        """,
    }
    scripts = ", ".join(f"'behaviour_{i} = swarm.behaviour_{i}:main'" for i in range(patterns))
    files["swarm/setup.py"] = f"""
        from setuptools import setup

        setup(name='swarm', packages=['swarm'], entry_points={{'console_scripts': [{scripts}]}})
    """
    nodes = "".join(f"\n        Node(package='swarm', executable='behaviour_{i}', namespace='robot_1'),"
                    for i in range(patterns))
    files["swarm/launch/robot.launch.py"] = f"""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([{nodes}
    ])
"""
    for index in range(patterns):
        message = "String" if index % 2 else "Int32"
        files[f"swarm/swarm/behaviour_{index}.py"] = f"""
            from std_msgs.msg import {message}

            from swarm.base import Behaviour
            from swarm.spin import init_and_spin


            class Behaviour{index}(Behaviour):
                def __init__(self):
                    super().__init__('behaviour_{index}')
                    self.out = self.create_publisher({message}, 'behaviour_{index}/out', 10)
                    self.message = {message}()
                    self.create_timer(0.5, self.gated(self.tick))

                def tick(self):
                    self.out.publish(self.message)


            def main(args=None):
                init_and_spin(args, Behaviour{index})
        """
    return files


def test_classes_handed_to_a_shared_helper_keep_their_own_nodes(tmp_path: Path) -> None:
    """Past the per-function context bound, the classes and functions passed still decide what
    runs: each of twelve executables builds its own node, and objects of different classes
    never share fields (no cross-class publish type mismatch)."""
    from flake8_rosgraph.launch.api import judged_graph
    from flake8_rosgraph.rules import RuleConfig, run_rules

    write(tmp_path, _pattern_package(12))
    found = publishers(tmp_path)
    for index in range(12):
        assert found.get(f"/behaviour_{index}") == [f"/behaviour_{index}/out"], found
    graph = build_graph(tmp_path)
    launched = sorted((n.executable, n.target.status) for s in graph.systems for n in s.nodes)
    assert launched == sorted((f"behaviour_{i}", "found") for i in range(12))  # every launch tied to its code
    judged = judged_graph(graph, graph.systems)
    assert {n.fqn for n in judged.nodes} >= {f"/robot_1/behaviour_{i}" for i in range(12)}
    assert run_rules(judged, RuleConfig(), ["ROS104"]) == []


FRAMEWORK_PACKAGE = {
    "robot_cli/package.xml": PACKAGE_XML.format(name="robot_cli", build="ament_python").replace(
        "</export>", "<rqt_gui plugin=\"${prefix}/plugin.xml\"/></export>"),
    "robot_cli/plugin.xml": """
        <library path="src">
          <class name="BatteryMonitor" type="robot_cli.monitor.BatteryMonitor" base_class_type="rqt_gui_py::Plugin"/>
          <class name="Native" type="robot_cli::NativePlugin" base_class_type="rqt_gui_cpp::Plugin"/>
        </library>
    """,
    "robot_cli/setup.py": """
        from setuptools import setup

        setup(name='robot_cli', packages=['robot_cli'], entry_points={
            'ros2cli.command': ['robot = robot_cli.command:RobotCommand'],
            'robot_cli.verb': ['dock = robot_cli.verbs:DockVerb'],
        })
    """,
    "robot_cli/robot_cli/__init__.py": "",
    "robot_cli/robot_cli/base.py": """
        class VerbBase:
            def add_arguments(self, parser, cli_name):
                pass
    """,
    "robot_cli/robot_cli/verbs.py": """
        import rclpy
        from std_srvs.srv import Trigger

        from robot_cli.base import VerbBase


        class DockVerb(VerbBase):
            def main(self, *, args):
                node = rclpy.create_node('dock_cli')
                client = node.create_client(Trigger, '/dock')
                return client.call(Trigger.Request())
    """,
    "robot_cli/robot_cli/command.py": """
        class RobotCommand:
            def main(self, *, parser, args):
                return 0
    """,
    "robot_cli/robot_cli/monitor.py": """
        from rclpy.node import Node
        from sensor_msgs.msg import BatteryState


        class Proxy:
            '''Forwards what it lacks to the node it wraps.'''
            def __init__(self, node):
                self._node = node

            def __getattr__(self, name):
                return getattr(self._node, name)


        class BatteryMonitor:
            def __init__(self, context):
                self.node = Proxy(Node('battery_monitor'))

            def start(self, topic='/battery_state'):
                # the plugin host calls it with the topic the user picks: not the default
                self.node.create_subscription(BatteryState, topic, self.on_state, 10)

            def restore(self):
                self.node.create_subscription(BatteryState, '/battery_alarm', self.on_state, 10)

            def on_state(self, msg):
                pass
    """,
}


def test_classes_frameworks_instantiate_are_entry_points(tmp_path: Path) -> None:
    """CLI verbs registered as entry points and rqt plugins exported in plugin.xml are built by
    their framework; their public methods nobody calls run with unknown arguments."""
    from flake8_rosgraph.registrations import registered_classes

    write(tmp_path, FRAMEWORK_PACKAGE)
    registered, diagnostics = registered_classes(tmp_path)
    assert (set(registered), diagnostics) == ({"robot_cli.command.RobotCommand", "robot_cli.verbs.DockVerb",
                                               "robot_cli.monitor.BatteryMonitor"}, [])
    graph = build_graph(tmp_path)
    ends = {(n.fqn, e.kind, e.name) for n in graph.nodes for e in n.entities
            if e.kind in ("clients", "subscriptions")}
    assert ("/dock_cli", "clients", "/dock") in ends
    assert ("/battery_monitor", "subscriptions", "/battery_alarm") in ends  # through __getattr__
    # the topic the host passes is unknown: never the default '/battery_state'
    assert ("/battery_monitor", "subscriptions", None) in ends
    assert not any(name == "/battery_state" for _, _, name in ends)


def test_hostile_framework_metadata_costs_only_its_registrations(tmp_path: Path) -> None:
    """A plugin description that expands entities, nests without end or is not XML, and entry
    points that are not ``module:Class``, register nothing; the package is still analysed and
    the diagnostic names it."""
    from flake8_rosgraph.registrations import registered_classes

    files = dict(FRAMEWORK_PACKAGE)
    files["robot_cli/plugin.xml"] = ('<!DOCTYPE l [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;">]>'
                                     '<library><class type="robot_cli.monitor.BatteryMonitor">&b;</class></library>')
    files["robot_cli/setup.py"] = files["robot_cli/setup.py"].replace(
        "'robot_cli.verb': ['dock = robot_cli.verbs:DockVerb'],",
        "'robot_cli.verb': ['dock = robot_cli.verbs:DockVerb', 'bad = not a target', 42],")
    write(tmp_path, files)
    registered, diagnostics = registered_classes(tmp_path)
    # the entry points still count; the malformed ones and the refused plugin.xml do not
    assert set(registered) == {"robot_cli.command.RobotCommand", "robot_cli.verbs.DockVerb"}
    assert [(d.path, d.line) for d in diagnostics] == [("robot_cli/package.xml", 1)]
    assert "DOCTYPE" in diagnostics[0].message
    graph = build_graph(tmp_path)
    assert any(d.path == "robot_cli/package.xml" and "framework" in d.message for d in graph.diagnostics)
    deep = tmp_path / "deep"
    write(deep, dict(FRAMEWORK_PACKAGE, **{"robot_cli/plugin.xml": "<a>" * 5000 + "</a>" * 5000}))
    registered, diagnostics = registered_classes(deep)
    assert set(registered) == {"robot_cli.command.RobotCommand", "robot_cli.verbs.DockVerb"}
    assert ["nested deeper" in d.message for d in diagnostics] == [True]


def test_cached_properties_are_read_like_properties(tmp_path: Path) -> None:
    """``functools.cached_property`` getters run when read: the clients they create are found."""
    write(tmp_path, {
        "arm/package.xml": PACKAGE_XML.format(name="arm", build="ament_python"),
        "arm/arm/__init__.py": "",
        "arm/arm/client.py": """
            from functools import cached_property

            import rclpy
            from rclpy.node import Node
            from std_srvs.srv import Trigger


            class ArmClient(Node):
                def __init__(self):
                    super().__init__('arm_client')

                @cached_property
                def _home(self):
                    return self.create_client(Trigger, 'arm/home')

                def go_home(self):
                    return self._home.call_async(Trigger.Request())


            def main():
                rclpy.init()
                client = ArmClient()
                client.go_home()
        """,
    })
    graph = build_graph(tmp_path)
    assert {(n.fqn, e.name) for n in graph.nodes for e in n.entities if e.kind == "clients"} == \
        {("/arm_client", "/arm/home")}
