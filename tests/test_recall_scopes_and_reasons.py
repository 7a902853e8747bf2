"""Extraction mechanisms found on a fourth round of real repositories outside every test set
(a framework's node made inside a ``@contextmanager`` scope and entered through an
``ExitStack``, pytest fixtures yielding that scope), and ``--explain`` reasons that were wrong
or missing there (a call in a branch that only an early, superseded run took; names left
unknown by a budget that stopped the analysis; names built from attributes in an f-string).
Each on a realistic multi-file workspace, with a twin where following the code must not
invent a name or an entity."""
from __future__ import annotations

from pathlib import Path

import pytest

from flake8_rosgraph.absint import engine
from flake8_rosgraph.analysis import analyse
from flake8_rosgraph.explain import explain
from flake8_rosgraph.graph.builder import _entity_order
from flake8_rosgraph.graph.model import Entity, Location

from test_recall_mechanisms import entities
from test_workspace_discovery import PACKAGE_XML, setup_py, write


def reasons(root: Path) -> dict[tuple[str, int], tuple[str, tuple[str, ...]]]:
    """``(path, line) -> (status, reasons)`` of every creation site ``--explain`` lists."""
    graph, analyses = analyse(root)
    return {(e.site.path, e.site.line): (e.status, e.reasons)
            for e in explain(analyses, graph).explanations}


# -- a process scope: the node is made when the scope is entered ------------------------------
SCOPE = """
    import contextlib

    import rclpy
    from rclpy.node import Node


    class ProcessScope:
        '''Owns the process's main node while it is entered.'''

        def __init__(self, name='node', namespace=None):
            self._name = name
            self._namespace = namespace
            self._node = None

        def __enter__(self):
            self._node = Node(self._name, namespace=self._namespace)
            return self

        def __exit__(self, *exc):
            self._node.destroy_node()
            self._node = None

        @property
        def node(self):
            return self._node


    @contextlib.contextmanager
    def top(args=None, **kwargs):
        rclpy.init(args=args)
        stack = contextlib.ExitStack()
        try:
            yield stack.enter_context(ProcessScope(**kwargs))
        finally:
            stack.close()
            rclpy.shutdown()


    @contextlib.contextmanager
    def remote_settings(path):
        with open(path) as stream:
            yield load_settings(stream)
"""

SCOPED = {
    "scoped_apps/package.xml": PACKAGE_XML.format(name="scoped_apps", build="ament_python"),
    "scoped_apps/setup.py": setup_py("scoped_apps", "'talker = scoped_apps.talker:main', "
                                                  "'relay = scoped_apps.relay:main'"),
    "scoped_apps/scoped_apps/__init__.py": "",
    "scoped_apps/scoped_apps/scope.py": SCOPE,
    "scoped_apps/scoped_apps/talker.py": """
        from std_msgs.msg import String

        from scoped_apps import scope


        def main():
            with scope.top(name='talker') as process:
                process.node.create_publisher(String, 'chatter', 10)
    """,
    "scoped_apps/scoped_apps/relay.py": """
        from std_msgs.msg import String
        from std_srvs.srv import Trigger

        from scoped_apps.scope import top


        def main():
            with top(name='relay', namespace='bridge') as process:
                node = process.node
                node.create_subscription(String, 'chatter', lambda msg: None, 10)
                node.create_service(Trigger, 'reset', lambda request, response: response)
    """,
    "scoped_apps/test/conftest.py": """
        import pytest

        from scoped_apps import scope


        @pytest.fixture
        def ros():
            with scope.top(namespace='fixture') as top:
                yield top
    """,
    "scoped_apps/test/test_reset.py": """
        from std_srvs.srv import Trigger

        from scoped_apps.scope import ProcessScope


        def test_reset_client(ros: ProcessScope):
            client = ros.node.create_client(Trigger, 'reset')
            assert client.wait_for_service(timeout_sec=1.0)
    """,
}


def test_a_node_made_when_a_contextmanager_scope_is_entered_gets_its_entities(
        tmp_path: Path) -> None:
    """``with top(...) as process`` is what the ``@contextmanager`` generator yields for that
    call, here what ``ExitStack.enter_context`` returns (the scope's ``__enter__``, which makes
    the node); a fixture yielding the scope from its own ``with`` hands it to the test
    (synchros2: 91 of 120 creation sites were not in the graph)."""
    root = write(tmp_path, SCOPED)
    kinds = ("publishers", "subscriptions", "services", "clients")
    assert entities(root, kinds) == {
        "/talker": [("publishers", "/chatter")],
        "/bridge/relay": [("services", "/bridge/reset"), ("subscriptions", "/bridge/chatter")],
        "/fixture/node": [("clients", "/fixture/reset")],
    }
    assert {status for status, _ in reasons(root).values()} == {"complete"}


def test_each_scope_call_keeps_its_own_node(tmp_path: Path) -> None:
    """Two calls of the same ``@contextmanager`` function in one function: each ``with`` gets
    what its own call yields, not the join of both (the relay's service is not the talker's),
    and a generator yielding what unknown code returns gives no node at all."""
    files = dict(SCOPED)
    files["scoped_apps/scoped_apps/talker.py"] = """
        from std_msgs.msg import String
        from std_srvs.srv import Trigger

        from scoped_apps import scope


        def main():
            with scope.top(name='talker') as first:
                first.node.create_publisher(String, 'chatter', 10)
            with scope.top(name='relay', namespace='bridge') as second:
                second.node.create_service(Trigger, 'reset', lambda request, response: response)
            with scope.remote_settings('/etc/robot.yaml') as settings:
                settings.node.create_publisher(String, 'settings_echo', 10)
    """
    got = entities(write(tmp_path, files), ("publishers", "services"))
    assert got["/talker"] == [("publishers", "/chatter")]
    assert ("services", "/bridge/reset") in got["/bridge/relay"]
    assert ("services", "/bridge/reset") not in got["/talker"]
    assert all(name != "/settings_echo" for ents in got.values() for _, name in ents)


# -- explain: a branch only a superseded run took --------------------------------------------
LOADER = {
    "model_loader/package.xml": PACKAGE_XML.format(name="model_loader", build="ament_python"),
    "model_loader/setup.py": setup_py("model_loader", "'loader = model_loader.loader_node:main'"),
    "model_loader/model_loader/__init__.py": "",
    "model_loader/model_loader/loader_config.py": """
        ENABLE_MODEL_OPTIMIZER = False
        OPTIMIZER_SERVICE = 'model_optimizer_pkg/model_optimizer_server'
        VERIFY_SERVICE = 'verify_model_ready'
    """,
    "model_loader/model_loader/loader_node.py": """
        import rclpy
        from rclpy.node import Node
        from std_srvs.srv import Trigger

        from model_loader import loader_config


        class ModelLoaderNode(Node):
            def __init__(self):
                super().__init__('model_loader_node')
                if loader_config.ENABLE_MODEL_OPTIMIZER:
                    self.optimizer = self.create_client(Trigger, loader_config.OPTIMIZER_SERVICE)
                else:
                    self.optimizer = None
                self.verify = self.create_service(Trigger, loader_config.VERIFY_SERVICE,
                                                  self.on_verify)

            def on_verify(self, request, response):
                response.success = True
                return response


        def main():
            rclpy.init()
            rclpy.spin(ModelLoaderNode())
    """,
}


def test_a_call_in_a_branch_the_final_run_rules_out_is_explained_as_never_reached(
        tmp_path: Path) -> None:
    """The first run of the constructor reads the configuration module's flag before that
    module ran (⊥) and evaluates both branches; the final run takes only ``else``. The client
    is not in the graph because the line never runs, not because ``self`` is no node
    (aws-deepracer-systems-pkg's model loader)."""
    root = write(tmp_path, LOADER)
    status, why = reasons(root)[("model_loader/model_loader/loader_node.py", 12)]
    assert status == "missing"
    assert why == ("the analysis never reaches this line (every path to it goes through a "
                   "branch, exception or call the analysis decided cannot get here)",)
    assert entities(root, ("services", "clients")) == {
        "/model_loader_node": [("services", "/verify_model_ready")]}


def test_a_call_in_a_branch_the_flag_opens_is_in_the_graph(tmp_path: Path) -> None:
    """The twin: with the flag set, the same line is reached and its client is there."""
    files = dict(LOADER)
    files["model_loader/model_loader/loader_config.py"] = files[
        "model_loader/model_loader/loader_config.py"].replace("= False", "= True")
    root = write(tmp_path, files)
    assert entities(root, ("services", "clients")) == {"/model_loader_node": [
        ("clients", "/model_optimizer_pkg/model_optimizer_server"),
        ("services", "/verify_model_ready")]}
    assert reasons(root)[("model_loader/model_loader/loader_node.py", 12)][0] == "complete"


# -- explain: names built from attributes, and names a stopped analysis left unknown ----------
LIFECYCLE = {
    "stack_composer/package.xml": PACKAGE_XML.format(name="stack_composer", build="ament_python"),
    "stack_composer/setup.py": setup_py("stack_composer", "'composer = stack_composer.composer:main'"),
    "stack_composer/stack_composer/__init__.py": "",
    "stack_composer/stack_composer/managed.py": """
        import rclpy
        from lifecycle_msgs.srv import GetState


        class ManagedNode:
            '''A node of a stack manifest, whose name and namespace the manifest gives.'''

            def __init__(self, manifest):
                self.name = manifest['name']
                self.namespace = manifest.get('namespace', '')

            def get_state(self):
                probe = rclpy.create_node('get_state_probe')
                client = probe.create_client(GetState, f'/{self.namespace}/{self.name}/get_state')
                future = client.call_async(GetState.Request())
                rclpy.spin_until_future_complete(probe, future, timeout_sec=3.0)
                probe.destroy_node()
                return future.result()
    """,
    "stack_composer/stack_composer/composer.py": """
        import json
        import sys

        import rclpy

        from stack_composer.managed import ManagedNode


        def main():
            rclpy.init()
            with open(sys.argv[1]) as stream:
                stack = json.load(stream)
            for manifest in stack['nodes']:
                print(ManagedNode(manifest).get_state())
    """,
}


def test_a_name_built_from_unknown_attributes_names_them(tmp_path: Path) -> None:
    """``f'/{self.namespace}/{self.name}/get_state'`` with both attributes read from a manifest
    file: the reason names each attribute, instead of no reason at all (muto composer)."""
    status, why = reasons(write(tmp_path, LIFECYCLE))[("stack_composer/stack_composer/managed.py", 14)]
    assert status == "unknown"
    assert why == ("unknown name", "`self.namespace` holds a value the analysis does not know here",
                   "`self.name` holds a value the analysis does not know here")


FLEET = """
    import rclpy
    from std_msgs.msg import String


    def unit_topic(depth):
        if depth == 0:
            return '/fleet'
        return unit_topic(depth - 1) + '/unit' + str(depth)


    def on_status(msg):
        pass


    rclpy.init()
    node = rclpy.create_node('fleet_monitor')
    for topic in (unit_topic(2), unit_topic(5)):
        node.create_subscription(String, topic, on_status, 10)
"""


def test_names_a_stopped_analysis_left_unknown_say_so(tmp_path: Path,
                                                      monkeypatch: pytest.MonkeyPatch) -> None:
    """When the budget of a module's entry points runs out, the tasks it abandons keep their
    entities with every name unknown: ``--explain`` says the budget did it and where its
    warning is, and nothing else (the node's namespace is not "left to rclpy"); with the
    budget it needs, the same sites are complete (synchros2's action tests)."""
    root = write(tmp_path, {"fleet_monitor.py": FLEET})
    assert {status for status, _ in reasons(root).values()} == {"complete"}
    monkeypatch.setattr(engine, "ENTRY_TASK_RUNS", 4)
    got = reasons(root)
    stopped = ("the analysis of module fleet_monitor was stopped by its budget before its values "
               "were final, so the names it creates are unknown (see the warning at "
               "fleet_monitor.py:5)")
    assert got[("fleet_monitor.py", 16)] == ("unknown", ("unknown name", "unknown namespace", stopped))
    assert got[("fleet_monitor.py", 18)] == ("unknown", ("unknown name", stopped))


def test_a_call_a_stopped_analysis_never_reached_says_so(tmp_path: Path,
                                                         monkeypatch: pytest.MonkeyPatch) -> None:
    """The budget stops ``main`` before the scope it enters has a node: the call is missing
    because of the budget, not because ``process.node`` is no node."""
    files = dict(SCOPED)
    files["scoped_apps/scoped_apps/fleet.py"] = """
        from std_msgs.msg import String

        from scoped_apps.scope import top


        def unit_topic(depth):
            if depth == 0:
                return '/fleet'
            return unit_topic(depth - 1) + '/unit' + str(depth)


        def main():
            with top(name='fleet') as process:
                for topic in (unit_topic(2), unit_topic(5)):
                    process.node.create_subscription(String, topic, print, 10)
    """
    files["scoped_apps/setup.py"] = setup_py("scoped_apps", "'fleet = scoped_apps.fleet:main'")
    root = write(tmp_path, files)
    assert reasons(root)[("scoped_apps/scoped_apps/fleet.py", 15)][0] == "complete"
    monkeypatch.setattr(engine, "ENTRY_TASK_RUNS", 9)
    status, why = reasons(root)[("scoped_apps/scoped_apps/fleet.py", 15)]
    assert status == "missing"
    assert why == ("the analysis of main was stopped by its budget before it reached this call "
                   "with a node (see the warning at scoped_apps/scoped_apps/fleet.py:6)",)


# -- entities that differ only in a name template's default -----------------------------------
def test_entities_differing_only_in_a_template_default_sort() -> None:
    """A parameter declared on one path and not on another (inside ``try``, or by a helper
    only some callers run) gives two entities at one site whose name templates differ only
    in the default, ``None`` against a text: the graph sorts them instead of the whole group
    of modules failing with an internal error (muto agent: 0 creation sites)."""
    where = Location("muto_agent/commands.py", 148, 26)
    known = Entity("publishers", None, location=where, type="muto_msgs/msg/MutoAction",
                   name_template=(("commands_to_agent_topic", "msg4"),))
    unset = Entity("publishers", None, location=where, type="muto_msgs/msg/MutoAction",
                   name_template=(("commands_to_agent_topic", None),))
    assert sorted([known, unset], key=_entity_order) == [unset, known]
    assert sorted([unset, known], key=_entity_order) == [unset, known]


# -- enum members ------------------------------------------------------------------------------
TELEOP = {
    "web_teleop/package.xml": PACKAGE_XML.format(name="web_teleop", build="ament_python"),
    "web_teleop/setup.py": setup_py("web_teleop", "'ik_control = web_teleop.ik_control:main'"),
    "web_teleop/web_teleop/__init__.py": "",
    "web_teleop/web_teleop/constants.py": """
        from enum import Enum


        class ControlMode(Enum):
            '''The control modes of the driver.'''

            POSITION = 'position'
            NAVIGATION = 'navigation'

            def get_service_name(self):
                return f'switch_to_{self.value}_mode'


        class Topics(Enum):
            JOINT_STATES = 'joint_states'
            ODOM = 'odom'


        class Frame(str, Enum):
            BASE = 'base_link'


        GOAL_TOPIC = {ControlMode.POSITION: 'position_goal', ControlMode.NAVIGATION: 'nav_goal'}
    """,
    "web_teleop/web_teleop/ik_control.py": """
        import rclpy
        from rclpy.node import Node
        from sensor_msgs.msg import JointState
        from std_msgs.msg import String
        from std_srvs.srv import Trigger

        from web_teleop.constants import GOAL_TOPIC, ControlMode, Frame, Topics


        class StretchIKControl(Node):
            def __init__(self, mode=ControlMode.NAVIGATION):
                super().__init__('stretch_ik_control')
                navigation_mode = ControlMode.NAVIGATION
                self.switch_client = self.create_client(Trigger, navigation_mode.get_service_name())
                self.joints = self.create_subscription(JointState, Topics.JOINT_STATES.value,
                                                       self.on_joints, 1)
                for topic in Topics:
                    self.create_publisher(String, 'echo/' + topic.name.lower(), 1)
                self.goal = self.create_publisher(String, GOAL_TOPIC[mode], 1)
                if mode == ControlMode.POSITION:
                    self.create_publisher(String, 'position_markers', 1)
                if mode in (ControlMode.NAVIGATION,):
                    self.create_publisher(String, 'navigation_markers', 1)
                self.frame = self.create_publisher(String, Frame.BASE + '/pose', 1)

            def on_joints(self, msg):
                pass


        def main():
            rclpy.init()
            rclpy.spin(StretchIKControl())
    """,
}


def test_enum_members_have_their_value_name_and_methods(tmp_path: Path) -> None:
    """``ControlMode.NAVIGATION.get_service_name()``, ``Topics.JOINT_STATES.value`` and
    ``for topic in Topics: … topic.name`` follow the members (stretch_web_teleop's IK control:
    the mode switch client had no name); a ``(str, Enum)`` member is still its string."""
    root = write(tmp_path, TELEOP)
    got = entities(root, ("publishers", "subscriptions", "clients"))
    assert got == {"/stretch_ik_control": [
        ("clients", "/switch_to_navigation_mode"),
        ("publishers", "/base_link/pose"),
        ("publishers", "/echo/joint_states"),
        ("publishers", "/echo/odom"),
        ("publishers", "/nav_goal"),
        ("publishers", "/navigation_markers"),
        ("subscriptions", "/joint_states")]}
    assert {key: status for key, (status, _) in reasons(root).items() if status != "complete"} \
        == {("web_teleop/web_teleop/ik_control.py", 21): "missing"}  # mode is NAVIGATION


def test_enum_members_are_equal_only_to_themselves(tmp_path: Path) -> None:
    """The twin: a table keyed by members gives the value of the member looked up, not every
    value; ``==`` and ``in`` on members decide their branches; a pure enum's member in an
    f-string is not its value (``str()`` is ``ControlMode.NAVIGATION``): no name at all."""
    files = dict(TELEOP)
    files["web_teleop/web_teleop/ik_control.py"] = TELEOP["web_teleop/web_teleop/ik_control.py"].replace(
        "self.frame = self.create_publisher(String, Frame.BASE + '/pose', 1)",
        "self.frame = self.create_publisher(String, f'{mode}/status', 1)")
    got = entities(write(tmp_path, files), ("publishers",))["/stretch_ik_control"]
    assert ("publishers", "/position_goal") not in got
    assert ("publishers", "/position_markers") not in got
    assert ("publishers", "/navigation/status") not in got and ("publishers", "?") in got


# -- len() of a list the caller wrote ----------------------------------------------------------
HAL = {
    "hal_interfaces/package.xml": PACKAGE_XML.format(name="hal_interfaces", build="ament_python"),
    "hal_interfaces/setup.py": setup_py("hal_interfaces", "'vacuum_hal = hal_interfaces.hal:main'"),
    "hal_interfaces/hal_interfaces/__init__.py": "",
    "hal_interfaces/hal_interfaces/bumper.py": """
        from gazebo_msgs.msg import ContactsState
        from rclpy.node import Node


        class BumperNode(Node):
            def __init__(self, topics):
                super().__init__('bumper_node')
                self.topics = topics
                self.callbacks_ = [self.right_callback, self.center_callback, self.left_callback]
                for i in range(len(self.topics)):
                    self.sub = self.create_subscription(
                        ContactsState, topics[i], self.callbacks_[i], 10)
                self.contact_states_ = [ContactsState() for _ in range(3)]

            def right_callback(self, contact):
                self.contact_states_[0] = contact

            def center_callback(self, contact):
                self.contact_states_[1] = contact

            def left_callback(self, contact):
                self.contact_states_[2] = contact
    """,
    "hal_interfaces/hal_interfaces/hal.py": """
        import rclpy

        from hal_interfaces.bumper import BumperNode


        def main():
            rclpy.init()
            bumper_node = BumperNode([
                '/roombaROS/events/right_bumper',
                '/roombaROS/events/center_bumper',
                '/roombaROS/events/left_bumper',
            ])
            rclpy.spin(bumper_node)
    """,
}


def test_an_index_loop_over_a_written_list_follows_its_items(tmp_path: Path) -> None:
    """``for i in range(len(self.topics))`` over the list the caller wrote: ``len`` is known,
    so ``topics[i]`` is each of its items (RoboticsAcademy's bumper HAL)."""
    root = write(tmp_path, HAL)
    assert entities(root, ("subscriptions",)) == {"/bumper_node": [
        ("subscriptions", "/roombaROS/events/center_bumper"),
        ("subscriptions", "/roombaROS/events/left_bumper"),
        ("subscriptions", "/roombaROS/events/right_bumper")]}


def test_the_length_of_a_list_unseen_code_fills_stays_unknown(tmp_path: Path) -> None:
    """The twin: the list starts empty and a library the analysis does not see fills it, so
    its length decides nothing: the loop is not dead and invents no name."""
    files = dict(HAL)
    files["hal_interfaces/hal_interfaces/hal.py"] = """
        import rclpy
        from roomba_config import load_bumper_topics

        from hal_interfaces.bumper import BumperNode


        def main():
            rclpy.init()
            topics = []
            load_bumper_topics(topics)
            rclpy.spin(BumperNode(topics))
    """
    assert entities(write(tmp_path, files), ("subscriptions",)) == {
        "/bumper_node": [("subscriptions", "?")]}


# -- loops over written-out tables -----------------------------------------------------------
AI_SERVER = {
    "ai_server/package.xml": PACKAGE_XML.format(name="ai_server", build="ament_python"),
    "ai_server/setup.py": setup_py("ai_server", "'ai_server = ai_server.server:main'"),
    "ai_server/ai_server/__init__.py": "",
    "ai_server/ai_server/topics.py": """
        from std_msgs.msg import Bool, String

        STATUS_TOPICS = [('status', String), ('enabled', Bool)]
    """,
    "ai_server/ai_server/server.py": """
        import rclpy
        from example_interfaces.action import Fibonacci
        from rclpy.action import ActionServer
        from rclpy.node import Node
        from std_srvs.srv import Empty, SetBool, Trigger

        from ai_server.topics import STATUS_TOPICS


        class AIServer(Node):
            def __init__(self):
                super().__init__('physical_ai_server')
                service_definitions = [
                    ('/task/command', Trigger, self.on_command),
                    ('/set_robot_type', SetBool, self.on_robot_type),
                    ('/training/command', Trigger, self.on_command),
                    ('/training/get_user_list', Empty, self.on_user_list),
                    ('/training/get_dataset_list', Empty, self.on_user_list),
                    ('/training/get_model_weight_list', Empty, self.on_user_list),
                    ('/huggingface/control', SetBool, self.on_robot_type),
                    ('/get_policy_list', Empty, self.on_user_list),
                    ('/get_saved_policies', Empty, self.on_user_list),
                    ('/register_hf_user', SetBool, self.on_robot_type),
                    ('/get_registered_hf_user', Empty, self.on_user_list),
                    ('/get_robot_types', Empty, self.on_user_list),
                    ('/training/get_training_info', Trigger, self.on_command),
                ]
                for service_name, service_type, callback in service_definitions:
                    self.create_service(service_type, service_name, callback)
                for name, msg_type in STATUS_TOPICS:
                    self.create_publisher(msg_type, '~/' + name, 10)
                for action, execute in {'replay': self.on_replay}.items():
                    ActionServer(self, Fibonacci, action, execute)

            def on_command(self, request, response):
                return response

            def on_robot_type(self, request, response):
                return response

            def on_user_list(self, request, response):
                return response

            def on_replay(self, goal_handle):
                return Fibonacci.Result()


        def main():
            rclpy.init()
            rclpy.spin(AIServer())
    """,
}


def _typed(root: Path) -> list[tuple[str, str, str | None, str | None]]:
    return sorted((e.kind, e.name or "?", e.type, e.callback) for node in analyse(root)[0].nodes
                  for e in node.entities if e.kind in ("services", "publishers", "action_servers"))


def test_a_loop_over_a_table_creates_each_row_with_its_own_type(tmp_path: Path) -> None:
    """``for service_name, service_type, callback in service_definitions`` over thirteen
    written-out rows: each service has its own name, type and callback (physical_ai_tools'
    server: one service of unknown name before, the table being longer than a value holds);
    the same for a module's topic table and a dict's items."""
    root = write(tmp_path, AI_SERVER)
    got = _typed(root)
    assert len([g for g in got if g[0] == "services"]) == 13
    assert ("services", "/set_robot_type", "std_srvs/srv/SetBool", "AIServer.on_robot_type") in got
    assert ("services", "/get_robot_types", "std_srvs/srv/Empty", "AIServer.on_user_list") in got
    assert ("services", "/training/command", "std_srvs/srv/Trigger", "AIServer.on_command") in got
    assert ("publishers", "/physical_ai_server/enabled", "std_msgs/msg/Bool", None) in got
    assert ("publishers", "/physical_ai_server/status", "std_msgs/msg/String", None) in got
    assert ("action_servers", "/replay", "example_interfaces/action/Fibonacci",
            "AIServer.on_replay") in got
    assert {status for status, _ in reasons(root).values()} == {"complete"}


def test_a_table_handed_to_a_workspace_helper_is_not_paired_by_guess(tmp_path: Path) -> None:
    """The twin: the row goes through the workspace's own helper, which is not split per row
    (each row would be a calling context of its own); and a loop variable reassigned from
    something unknown is no longer the row's. Neither pairs a name with another row's type:
    thirteen names are more than a value holds, so each type comes with an unknown name."""
    files = dict(AI_SERVER)
    server = AI_SERVER["ai_server/ai_server/server.py"]
    files["ai_server/ai_server/server.py"] = server.replace(
        "                    self.create_service(service_type, service_name, callback)",
        "                    add_service(self, service_type, service_name, callback)").replace(
        "                    self.create_publisher(msg_type, '~/' + name, 10)",
        "                    name = self.topic_prefix() + name\n"
        "                    self.create_publisher(msg_type, name, 10)") + """

        def add_service(node, service_type, name, callback):
            return node.create_service(service_type, name, callback)
    """
    got = _typed(write(tmp_path, files))
    services = [g for g in got if g[0] == "services"]
    assert services and {name for _, name, _, _ in services} == {"?"}
    assert [g for g in got if g[0] == "publishers"] == [
        ("publishers", "?", "std_msgs/msg/Bool", None), ("publishers", "?", "std_msgs/msg/String", None)]


def test_rows_from_zip_enumerate_and_comprehensions_stay_paired(tmp_path: Path) -> None:
    """``zip`` of two written-out lists and ``enumerate`` of one give rows of known items, and
    a comprehension over a table is split per row like a loop: each publisher keeps its own
    type; a ``zip`` with a list that unseen code fills keeps its names unknown."""
    files = dict(AI_SERVER)
    files["ai_server/ai_server/arms.py"] = """
        import rclpy
        from rclpy.node import Node
        from sensor_msgs.msg import JointState
        from std_msgs.msg import Float64MultiArray

        from ai_server.topics import STATUS_TOPICS


        class ArmBridge(Node):
            def __init__(self):
                super().__init__('arm_bridge')
                arms = ['leader', 'follower']
                kinds = [JointState, Float64MultiArray]
                for arm, kind in zip(arms, kinds):
                    self.create_subscription(kind, arm + '/joint_states', self.on_joints, 10)
                for index, arm in enumerate(arms, 1):
                    self.create_publisher(JointState, f'arm{index}/{arm}/command', 10)
                self.status = {name: self.create_publisher(msg_type, 'bridge/' + name, 10)
                               for name, msg_type in STATUS_TOPICS}
                extra = []
                load_extra_arms(extra)
                for arm, kind in zip(extra, kinds):
                    self.create_subscription(kind, arm + '/extra', self.on_joints, 10)

            def on_joints(self, msg):
                pass


        def main():
            rclpy.init()
            rclpy.spin(ArmBridge())
    """
    files["ai_server/setup.py"] = setup_py("ai_server", "'ai_server = ai_server.server:main', "
                                                      "'arms = ai_server.arms:main'")
    root = write(tmp_path, files)
    got = sorted((e.kind, e.name or "?", e.type) for node in analyse(root)[0].nodes
                 if node.name == "arm_bridge" for e in node.entities
                 if e.kind in ("publishers", "subscriptions"))
    assert got == [
        ("publishers", "/arm1/leader/command", "sensor_msgs/msg/JointState"),
        ("publishers", "/arm2/follower/command", "sensor_msgs/msg/JointState"),
        ("publishers", "/bridge/enabled", "std_msgs/msg/Bool"),
        ("publishers", "/bridge/status", "std_msgs/msg/String"),
        ("subscriptions", "/follower/joint_states", "std_msgs/msg/Float64MultiArray"),
        ("subscriptions", "/leader/joint_states", "sensor_msgs/msg/JointState"),
        ("subscriptions", "?", "sensor_msgs/msg/JointState"),
        ("subscriptions", "?", "std_msgs/msg/Float64MultiArray"),
    ]


# -- property setters --------------------------------------------------------------------------
SETTERS = {
    "scope_setters/package.xml": PACKAGE_XML.format(name="scope_setters", build="ament_python"),
    "scope_setters/setup.py": setup_py("scope_setters", "'relay = scope_setters.relay:main'"),
    "scope_setters/scope_setters/__init__.py": "",
    "scope_setters/scope_setters/scope.py": """
        class Scope:
            '''Holds the process's main node once one is promoted to it.'''

            def __init__(self):
                self._node = None
                self._prefix = '/robot'

            @property
            def node(self):
                return self._node

            @node.setter
            def node(self, node):
                if self._node is not None:
                    raise RuntimeError('main node already set')
                self._node = node

            @property
            def topic_prefix(self):
                return self._prefix

            @topic_prefix.setter
            def topic_prefix(self, robot_name):
                self._prefix = '/' + robot_name
    """,
    "scope_setters/scope_setters/relay.py": """
        import rclpy
        from rclpy.node import Node
        from std_msgs.msg import String

        from scope_setters.scope import Scope


        def main():
            rclpy.init()
            scope = Scope()
            scope.node = Node('relay')
            scope.topic_prefix = 'rover'
            scope.node.create_publisher(String, scope.topic_prefix + '/chatter', 10)
            rclpy.spin(scope.node)
    """,
}


def test_assigning_a_property_runs_its_setter(tmp_path: Path) -> None:
    """``scope.node = Node('relay')`` runs the ``node`` setter, which keeps the node where
    the getter reads it; ``scope.topic_prefix = 'rover'`` stores ``'/rover'``, not
    ``'rover'``: the publisher is never named from the assigned text itself (a confident wrong
    name before), and the setter is never what reading the property gives."""
    got = entities(write(tmp_path, SETTERS), ("publishers",))
    assert ("publishers", "/rover/chatter") in got["/relay"]
    assert ("publishers", "/chatter") not in got["/relay"]
    assert ("publishers", "rover/chatter") not in got["/relay"]


def test_a_parameter_with_a_default_on_some_paths_says_so(tmp_path: Path) -> None:
    """The topic parameter is declared with a default on one branch and without one on the
    other: the name is known only partly, and the reason says the default is missing on some
    paths, not everywhere (muto agent's commands node)."""
    files = {
        "agent_commands/package.xml": PACKAGE_XML.format(name="agent_commands", build="ament_python"),
        "agent_commands/setup.py": setup_py("agent_commands", "'commands = agent_commands.commands:main'"),
        "agent_commands/agent_commands/__init__.py": "",
        "agent_commands/agent_commands/commands.py": """
            import sys

            import rclpy
            from rclpy.node import Node
            from std_msgs.msg import String


            class CommandsNode(Node):
                def __init__(self, use_defaults):
                    super().__init__('commands')
                    if use_defaults:
                        self.declare_parameter('commands_to_agent_topic', 'msg4')
                    else:
                        self.declare_parameter('commands_to_agent_topic')
                    topic = self.get_parameter('commands_to_agent_topic').value
                    self.pub = self.create_publisher(String, topic, 10)


            def main():
                rclpy.init()
                rclpy.spin(CommandsNode('--defaults' in sys.argv))
        """,
    }
    status, why = reasons(write(tmp_path, files))[("agent_commands/agent_commands/commands.py", 16)]
    assert status == "unknown"
    assert why[0].startswith("unknown name (known only partly: '/msg4' on some paths")
    assert why[1] == ("it is built from ROS parameter 'commands_to_agent_topic' of its node, with no "
                      "default in code that reaches this call on some paths; where a launch file sets "
                      "them, `graph --launch FILE` shows the name")
