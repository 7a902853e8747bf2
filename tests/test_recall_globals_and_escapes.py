"""Extraction mechanisms found on a fifth round of real repositories outside every test set:
an element of a parameter's list deciding a branch by its default; a node a function binds
to a module global it declares ``global``; test functions a factory hands out through
``locals()``; a module attribute set by the script that imports the module reading it; and
an import that only resolves because the module puts a folder on ``sys.path`` first; an
interface type only the star imports of one package's modules can bind. Each on
a realistic multi-file workspace, with a twin where following the code must not invent a
name or an entity."""
from __future__ import annotations

from pathlib import Path

from test_recall_mechanisms import entities
from test_recall_scopes_and_reasons import reasons
from test_workspace_discovery import PACKAGE_XML, setup_py, write

SERVICES = ("services", "clients")


def package(name: str, entries: str, modules: dict[str, str]) -> dict[str, str]:
    """An ament_python package ``name`` with these console scripts and modules."""
    files = {f"{name}/package.xml": PACKAGE_XML.format(name=name, build="ament_python"),
             f"{name}/setup.py": setup_py(name, entries),
             f"{name}/{name}/__init__.py": ""}
    files.update({f"{name}/{name}/{module}.py": text for module, text in modules.items()})
    return files


# -- elements of a parameter's list are defaults, not the run's values -------------------------
BUTTONS = """
    from dataclasses import dataclass

    import rclpy
    from rclpy.node import Node
    from sensor_msgs.msg import Joy
    from std_srvs.srv import Trigger


    @dataclass
    class Output:
        button: int
        topic: str | None = None
        service: str | None = None


    class ButtonRouter(Node):
        '''Routes each joystick button either to a topic or to a service.'''

        def __init__(self):
            super().__init__('button_router')
            self.declare_parameter('buttons', [0])
            self.declare_parameter('is_service', [False])
            self.declare_parameter('targets', [''])
            buttons = self.get_parameter('buttons').get_parameter_value().integer_array_value
            is_service = self.get_parameter('is_service').get_parameter_value().bool_array_value
            targets = self.get_parameter('targets').get_parameter_value().string_array_value
            self.outputs: list[Output] = []
            for i in range(len(buttons)):
                output = Output(buttons[i])
                if is_service[i]:
                    output.service = targets[i]
                else:
                    output.topic = targets[i]
                self.outputs.append(output)
            if is_service[0]:
                self.create_service(Trigger, 'first_is_service', self.on_first)
            for output in self.outputs:
                if output.service is not None:
                    self.create_client(Trigger, output.service)

        def on_first(self, request, response):
            return response


    def main():
        rclpy.init()
        rclpy.spin(ButtonRouter())
"""


def test_an_element_of_a_parameter_list_decides_no_branch(tmp_path: Path) -> None:
    """``is_service[i]`` and ``is_service[0]`` read the declared default ``[False]``, which
    the run may override: both branches exist in some configuration, so the service and the
    client (named by the run) are in the graph; ``len(buttons)`` is not the default's 1
    (rcdt_robotics: a client the analysis claimed could never be created)."""
    root = write(tmp_path, package("joy_router", "'router = joy_router.router:main'",
                                    {"router": BUTTONS}))
    assert entities(root, SERVICES) == {
        "/button_router": [("clients", "?"), ("services", "/first_is_service")]}
    statuses = {line: status for (path, line), (status, _) in reasons(root).items()}
    assert "never reached" not in " ".join(statuses.values())


def test_an_element_of_a_written_list_still_decides_its_branch(tmp_path: Path) -> None:
    """The twin: a list the code writes out is the run's, so ``flags[0]`` is ``False`` and
    the service under it is never created."""
    text = BUTTONS.replace("if is_service[0]:", "if [False, True][0]:")
    root = write(tmp_path, package("joy_router", "'router = joy_router.router:main'",
                                    {"router": text}))
    assert "/first_is_service" not in {
        name for _, name in entities(root, SERVICES)["/button_router"]}


# -- a node bound to a module global inside ``main`` -----------------------------------------
GLOBAL_NODE = """
    import rclpy
    from rclpy.node import Node
    from std_msgs.msg import String

    global node


    def on_message(msg):
        node.get_logger().info(msg.data)


    def main():
        global node
        rclpy.init()
        node = Node('echo')
        node.create_subscription(String, 'chatter', on_message, 10)
        rclpy.spin(node)
"""


def test_a_node_bound_to_a_declared_global_keeps_its_entities(tmp_path: Path) -> None:
    """``global node`` then ``node = Node('echo')`` in ``main`` binds the module's ``node``,
    which the callbacks read too (a module-level ``global node`` declares nothing); it was
    unknown, so the subscription was lost (ROS2_learning)."""
    root = write(tmp_path, package("echo", "'echo = echo.echo:main'", {"echo": GLOBAL_NODE}))
    assert entities(root, ("subscriptions",)) == {"/echo": [("subscriptions", "/chatter")]}


def test_a_global_declared_but_never_bound_stays_unknown(tmp_path: Path) -> None:
    """The twin: ``main`` declares ``global node`` but binds a local of another name; the
    module never binds ``node``, so nothing is created on it."""
    text = GLOBAL_NODE.replace("node = Node('echo')\n", "other = Node('echo')\n")
    root = write(tmp_path, package("echo", "'echo = echo.echo:main'", {"echo": text}))
    assert entities(root, ("subscriptions",)) == {"/echo": []}


# -- tests a factory hands out through ``locals()`` -----------------------------------------
FACTORY = """
    from rclpy.node import Node
    from std_msgs.msg import String
    from std_srvs.srv import Trigger


    def make_tests(robot: str) -> dict:
        '''The tests of one robot, attached to a class per robot by the test modules.'''

        def test_reset_service(_self, node: Node) -> None:
            client = node.create_client(Trigger, f'/{robot}/reset')
            assert client.wait_for_service(timeout_sec=1.0)

        def test_status_published(_self, node: Node) -> None:
            node.create_subscription(String, f'/{robot}/status', lambda msg: None, 10)

        def helper() -> None:
            pass

        return {name: obj for name, obj in locals().items() if name.startswith('test_')}
"""
FACTORY_TEST = """
    from fleet_tests.shared import make_tests


    def add_tests(cls, tests):
        for name, method in tests.items():
            setattr(cls, name, method)


    class TestAlpha:
        '''Alpha's tests.'''


    add_tests(TestAlpha, make_tests('alpha'))
    TestBeta = type('TestBeta', (object,), make_tests('beta'))
"""


def test_functions_handed_out_through_locals_are_analysed(tmp_path: Path) -> None:
    """``locals()`` gives away every function the factory defines: the class built with
    ``type`` (or filled with ``setattr``) makes them tests pytest calls, so they are entries,
    here with an unknown node (rcdt_robotics: five creation sites never called)."""
    files = package("fleet_tests", "", {"shared": FACTORY})
    files["fleet_tests/test/test_fleet.py"] = FACTORY_TEST
    root = write(tmp_path, files)
    found = reasons(root)
    shared = {line: (status, why) for (path, line), (status, why) in found.items()
              if path.endswith("shared.py")}
    assert len(shared) == 2
    assert all("never called" not in " ".join(why) for _, why in shared.values())


CONFTEST = """
    import pytest
    import rclpy
    from rclpy.node import Node


    @pytest.fixture(scope='module')
    def node():
        rclpy.init()
        test_node = Node('tester')
        yield test_node
        test_node.destroy_node()
"""


def test_a_factory_made_test_gets_the_fixtures_of_its_folder(tmp_path: Path) -> None:
    """pytest runs the factory's tests as methods of the classes it builds, passing the
    fixtures a ``conftest.py`` above defines: ``node`` is the fixture's node, so the
    tests' entities are on it, each robot's under its name."""
    files = package("fleet_tests", "", {"shared": FACTORY})
    files["fleet_tests/test/test_fleet.py"] = FACTORY_TEST
    files["conftest.py"] = CONFTEST
    root = write(tmp_path, files)
    assert entities(root, ("clients", "subscriptions"))["/tester"] == [
        ("clients", "/alpha/reset"), ("clients", "/beta/reset"),
        ("subscriptions", "/alpha/status"), ("subscriptions", "/beta/status")]


def test_a_nested_helper_called_with_its_own_node_keeps_it(tmp_path: Path) -> None:
    """The twin: a nested ``test*`` function its factory calls itself with a node of its own
    takes that node, not the fixture of the same name."""
    text = FACTORY.replace(
        "return {name: obj for name, obj in locals().items() if name.startswith('test_')}",
        "test_reset_service(None, Node(f'{robot}_checker'))\n        return {}")
    files = package("fleet_tests", "", {"shared": text})
    files["fleet_tests/test/test_fleet.py"] = FACTORY_TEST
    files["conftest.py"] = CONFTEST
    root = write(tmp_path, files)
    found = entities(root, ("clients",))
    assert ("clients", "/alpha/reset") in found["/alpha_checker"]
    assert found["/tester"] == []


def test_functions_a_factory_keeps_to_itself_are_not_entries(tmp_path: Path) -> None:
    """The twin: a factory that returns one named test (no ``locals()``) and a helper it
    never hands out: the helper's creation call stays never called."""
    text = FACTORY.replace(
        "return {name: obj for name, obj in locals().items() if name.startswith('test_')}",
        "return {'test_reset_service': test_reset_service}").replace(
        "def helper() -> None:\n            pass",
        "def helper(node: Node) -> None:\n            node.create_client(Trigger, 'unused')")
    files = package("fleet_tests", "", {"shared": text})
    files["fleet_tests/test/test_fleet.py"] = FACTORY_TEST
    root = write(tmp_path, files)
    by_line = {line: why for (path, line), (_, why) in reasons(root).items()
               if path.endswith("shared.py")}
    assert any("never called" in " ".join(why) for why in by_line.values())


# -- a module attribute the importing script sets, read by the module it then imports ---------
ROBOT_API = """
    import robot_init
    from std_srvs.srv import Trigger

    g_node = robot_init.__robot_node__
    _home = g_node.create_client(Trigger, 'motion/home')


    def home():
        return _home.call_async(Trigger.Request())
"""
ROBOT_INIT = """
    __robot_id__ = 'arm'
"""
ROBOT_SCRIPT = """
    import os
    import sys

    import rclpy

    sys.path.append(os.path.join(os.path.dirname(__file__), '../../../common/lib/api'))

    import robot_init
    rclpy.init()
    node = rclpy.create_node('home_arm')
    robot_init.__robot_node__ = node
    from robot_api import *


    def main():
        home()
        rclpy.spin(node)
"""


def _sdk(script: str) -> dict[str, str]:
    files = {"common/api/__init__.py": "",
             "common/api/robot_api.py": ROBOT_API,
             "common/api/robot_init.py": ROBOT_INIT}
    files.update(package("arm_examples", "'home = arm_examples.home:main'", {"home": script}))
    return files


def test_a_module_attribute_set_by_the_importer_is_read_by_the_module(tmp_path: Path) -> None:
    """The script sets ``robot_init.__robot_node__`` and then imports the API module, which
    reads it at its top level; the script finds both modules through the folder it puts on
    ``sys.path`` (doosan-robot2: 204 clients on an unknown node)."""
    root = write(tmp_path, _sdk(ROBOT_SCRIPT))
    assert entities(root, SERVICES) == {"/home_arm": [("clients", "/motion/home")]}


def test_without_the_sys_path_edit_the_bare_import_stays_a_library(tmp_path: Path) -> None:
    """The twin: the same script without the ``sys.path`` edit imports ``robot_init`` and
    ``robot_api`` from wherever Python finds them (an installed library), not from the
    workspace folder its package does not reach, so no client is invented on the node."""
    text = ROBOT_SCRIPT.replace(
        "sys.path.append(os.path.join(os.path.dirname(__file__), '../../../common/lib/api'))\n", "")
    root = write(tmp_path, _sdk(text))
    assert entities(root, SERVICES).get("/home_arm") == []


def test_an_attribute_nothing_sets_on_the_module_creates_nothing(tmp_path: Path) -> None:
    """The twin: nobody sets ``robot_init.__robot_node__`` (the script keeps the node), so
    reading it would raise: no client is made on any node."""
    text = ROBOT_SCRIPT.replace("    robot_init.__robot_node__ = node\n", "")
    root = write(tmp_path, _sdk(text))
    assert entities(root, SERVICES).get("/home_arm") == []


# -- names only a library's ``import *`` can bind -------------------------------------------
STAR_CLIENT = """
    import rclpy
    from arm_msgs.msg import *
    from arm_msgs.srv import *


    def main():
        rclpy.init()
        node = rclpy.create_node('mode_switch')
        client = node.create_client(SetMode, 'system/set_mode')
        node.create_publisher(Mode, 'mode', 10)
        client.wait_for_service()
"""


def _types(root: Path) -> dict[str, list[tuple[str, str | None]]]:
    """Each node's clients and publishers as ``(name, type)``."""
    from flake8_rosgraph.analysis import build_graph
    return {node.fqn: sorted((e.name, e.type) for e in node.entities
                             if e.kind in ("clients", "publishers"))
            for node in build_graph(root).nodes}


def test_a_name_from_star_imported_interface_modules_takes_the_fitting_type(
        tmp_path: Path) -> None:
    """``SetMode`` and ``Mode`` are bound by nothing in the module or the workspace: only the
    star imports of one package's ``msg`` and ``srv`` modules can bind them, and a client's
    type is the service, a publisher's the message (doosan-robot2: 210 creation sites of
    unknown type, explained by nothing)."""
    root = write(tmp_path, package("arm_tools", "'switch = arm_tools.switch:main'",
                                    {"switch": STAR_CLIENT}))
    assert _types(root) == {"/mode_switch": [("/mode", "arm_msgs/msg/Mode"),
                                             ("/system/set_mode", "arm_msgs/srv/SetMode")]}
    assert {status for status, _ in reasons(root).values()} == {"complete"}


def test_star_imports_of_two_packages_leave_the_type_unknown_and_say_why(
        tmp_path: Path) -> None:
    """The twin: with star imports of two packages' services, ``SetMode`` could be either
    one's: the type stays unknown (no second, invented client) and ``--explain`` says that
    only those imports can bind the name."""
    text = STAR_CLIENT.replace("from arm_msgs.msg import *", "from gripper_msgs.srv import *")
    root = write(tmp_path, package("arm_tools", "'switch = arm_tools.switch:main'",
                                    {"switch": text}))
    assert _types(root)["/mode_switch"] == [("/mode", None), ("/system/set_mode", None)]
    whys = [why for status, why in reasons(root).values() if status == "unknown"]
    assert any("`SetMode` can only come from `from … import *` of `arm_msgs.srv`, "
               "`gripper_msgs.srv`" in reason for why in whys for reason in why)


# -- a shared helper that creates what many callers name --------------------------------------
HELPERS = """
    from rclpy.node import Node


    def ready_client(node: Node, srv_type, name: str):
        '''A client that is ready to be called.'''
        client = node.create_client(srv_type, name)
        client.wait_for_service(timeout_sec=5.0)
        return client
"""


def _suite(calls: int) -> dict[str, str]:
    """A test calling the helper ``calls`` times, each with a service of its own."""
    lines = "\n".join(f"        ready_client(node, Trigger, '/robot/step_{i}')" for i in range(calls))
    test = f"""
    from std_srvs.srv import Trigger

    from bench.helpers import ready_client


    def test_every_step(node):
{lines}
"""
    files = package("bench", "", {"helpers": HELPERS})
    files["bench/test/test_steps.py"] = test
    files["conftest.py"] = CONFTEST
    return files


def test_a_helper_creating_entities_keeps_the_names_of_many_callers(tmp_path: Path) -> None:
    """A helper that creates the client its caller names keeps 24 calling contexts, not 8:
    twelve calls' services stay named (rcdt_robotics: a client lost when more tests
    called the helper)."""
    root = write(tmp_path, _suite(12))
    assert entities(root, ("clients",))["/tester"] == sorted(
        ("clients", f"/robot/step_{i}") for i in range(12))


def test_past_its_bound_a_helper_names_nothing_wrong(tmp_path: Path) -> None:
    """The twin: thirty callers exceed the bound; the names past it are unknown, never a
    name another caller passed."""
    root = write(tmp_path, _suite(30))
    names = {name for _, name in entities(root, ("clients",))["/tester"]} - {"?"}
    assert names < {f"/robot/step_{i}" for i in range(30)}
    assert len(names) == 24


def test_a_name_a_workspace_module_lacks_imported_from_it_stays_unknown(tmp_path: Path) -> None:
    """The twin of the module attribute set from outside: ``from robot_init import
    __robot_node__`` of a workspace module that never binds it (a library's name, shadowed)
    is unknown, not a missing value that would stop the script; the node keeps its
    publisher after the import."""
    script = ROBOT_SCRIPT.replace("    robot_init.__robot_node__ = node\n", "").replace(
        "from robot_api import *", "from robot_init import __robot_node__\n"
        "    __robot_node__.get_logger().info('arm ready')\n"
        "    node.create_publisher(String, 'status', 10)").replace(
        "import rclpy\n", "import rclpy\n    from std_msgs.msg import String\n", 1)
    files = _sdk(script)
    files["common/api/robot_state.py"] = "class State:\n    def bind(self, node):\n" \
                                         "        self.__robot_node__ = node\n"
    root = write(tmp_path, files)
    assert entities(root, ("publishers",)) == {"/home_arm": [("publishers", "/status")]}
