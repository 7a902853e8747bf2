"""Abstract interpretation of plain Python: values, heap, calls, termination (no ROS here)."""
from flake8_rosgraph.absint.values import TOP


def test_string_building_folds_to_constants(analyse):
    a = analyse({"m.py": """
        base = 'robot'
        idx = 2
        plus = base + '_' + str(idx)
        percent = '%s/%d' % (base, idx)
        fmt = '{}/{n}'.format(base, n=idx)
        fstr = f'{base}/{idx:03d}'
        joined = '/'.join([base, 'cmd'])
        upper = base.upper()
    """})
    assert a.strings("m", "plus") == ["robot_2"]
    assert a.strings("m", "percent") == ["robot/2"]
    assert a.strings("m", "fmt") == ["robot/2"]
    assert a.strings("m", "fstr") == ["robot/002"]
    assert a.strings("m", "joined") == ["robot/cmd"]
    assert a.strings("m", "upper") == ["ROBOT"]


def test_branches_give_a_set_of_values(analyse):
    a = analyse({"m.py": """
        import sys
        flag = len(sys.argv) > 1
        name = 'left' if flag else 'right'
        if flag:
            other = 'a'
        else:
            other = 'b'
        unknown = sys.argv[1]
    """})
    assert a.strings("m", "name") == ["left", "right"]
    assert a.strings("m", "other") == ["a", "b"]
    assert a.value("m", "unknown").is_top


def test_constant_conditions_prune_branches(analyse):
    a = analyse({"m.py": """
        DEBUG = False
        if DEBUG:
            mode = 'debug'
        else:
            mode = 'release'
    """})
    assert a.strings("m", "mode") == ["release"]


def test_growing_loop_value_widens_and_terminates(analyse):
    a = analyse({"m.py": """
        s = 'a'
        while True:
            s = s + 'a'
            if len(s) > 1000:
                break
        n = 0
        for i in range(10 ** 6):
            n = n + 1
    """})
    assert a.value("m", "s").is_top
    assert a.value("m", "n").is_top


def test_fields_written_in_one_method_are_read_in_another(analyse):
    a = analyse({"m.py": """
        class Box:
            PREFIX = 'box'
            def __init__(self, name):
                self.name = self.PREFIX + '/' + name
            def get(self):
                return self.name
        result = Box('one').get()
    """})
    assert a.strings("m", "result") == ["box/one"]


def test_inheritance_and_super_across_modules(analyse):
    a = analyse({
        "pkg/__init__.py": "from .base import Base\n",
        "pkg/base.py": """
            class Base:
                def __init__(self, topic):
                    self.topic = 'base/' + topic
                def describe(self):
                    return self.topic
        """,
        "pkg/child.py": """
            from pkg import Base
            class Child(Base):
                def __init__(self):
                    super().__init__('child')
            class Legacy(Base):
                def __init__(self):
                    super(Legacy, self).__init__('legacy')
            child = Child().describe()
            legacy = Legacy().describe()
        """})
    assert a.strings("pkg.child", "child") == ["base/child"]
    assert a.strings("pkg.child", "legacy") == ["base/legacy"]


def test_constants_imported_from_other_modules(analyse):
    a = analyse({
        "pkg/__init__.py": "",
        "pkg/names.py": "TOPIC = 'cmd_vel'\nNS = 'robot'\n",
        "pkg/use.py": """
            from . import names
            from .names import TOPIC as T
            import pkg.names as pn
            full = pn.NS + '/' + T + '/' + names.TOPIC
        """})
    assert a.strings("pkg.use", "full") == ["robot/cmd_vel/cmd_vel"]


def test_calls_are_context_sensitive(analyse):
    a = analyse({"m.py": """
        def prefixed(name):
            return '/ns/' + name
        first = prefixed('a')
        second = prefixed('b')
    """})
    assert a.strings("m", "first") == ["/ns/a"]
    assert a.strings("m", "second") == ["/ns/b"]


def test_closures_and_lambdas(analyse):
    a = analyse({"m.py": """
        def outer():
            suffix = 'x'
            def inner(v):
                return v + suffix
            return inner('a'), (lambda: suffix * 2)()
        pair = outer()
        first, second = pair
    """})
    assert a.strings("m", "first") == ["ax"]
    assert a.strings("m", "second") == ["xx"]


def test_recursion_terminates(analyse):
    a = analyse({"m.py": """
        def down(n):
            if n <= 0:
                return 'done'
            return down(n - 1)
        def ping(x):
            return pong(x + 'i')
        def pong(x):
            return ping(x + 'o')
        result = down(3)
        endless = ping('')
    """})
    assert a.strings("m", "result") == ["done"]
    assert not a.value("m", "endless").strings()


def test_containers_iterate_to_their_elements(analyse):
    a = analyse({"m.py": """
        topics = {'left': 'cam/left', 'right': 'cam/right'}
        names = []
        for key, value in topics.items():
            last = value
        for t in ('a', 'b'):
            loop_var = t
        firsts = [p for p in ['x', 'y']]
        picked = topics['left']
    """})
    assert a.strings("m", "last") == ["cam/left", "cam/right"]
    assert a.strings("m", "loop_var") == ["a", "b"]
    assert a.strings("m", "picked") == ["cam/left"]


def test_argparse_defaults_flow_to_attributes(analyse):
    a = analyse({"m.py": """
        import argparse
        parser = argparse.ArgumentParser()
        parser.add_argument('--topic-name', default='scan')
        parser.add_argument('robot', nargs='?', default='r1')
        args = parser.parse_args()
        topic = args.robot + '/' + args.topic_name
    """})
    assert a.strings("m", "topic") == ["r1/scan"]


def test_unknown_library_values_stay_unknown(analyse):
    a = analyse({"m.py": """
        import os
        import somelib
        name = os.environ['ROBOT']
        value = somelib.compute('x')
    """})
    assert a.value("m", "name") == TOP
    assert a.value("m", "value") == TOP


def test_overridable_defaults_name_things_but_do_not_prune_branches(analyse):
    a = analyse({"m.py": """
        import argparse
        parser = argparse.ArgumentParser()
        parser.add_argument('--fast', action='store_true', default=False)
        args = parser.parse_args()
        suffix = '_fast' if args.fast else ''
        if args.fast:
            mode = 'fast'
        else:
            mode = 'slow'
    """})
    # the default configuration names the value …
    assert a.strings("m", "suffix") == [""]
    # … but code under the option is still reachable
    assert a.strings("m", "mode") == ["fast", "slow"]
    assert a.value("m", "mode").soft is False  # literals are not defaults


def test_records_are_updated_through_their_variable(analyse):
    a = analyse({"m.py": """
        from rclpy.qos import QoSProfile, ReliabilityPolicy
        profile = QoSProfile(depth=5)
        profile.reliability = ReliabilityPolicy.BEST_EFFORT
        reliability = profile.reliability
        depth = profile.depth
    """})
    [atom] = list(a.value("m", "reliability"))
    assert atom.qualname == "rclpy.qos.ReliabilityPolicy.BEST_EFFORT"
    assert a.value("m", "depth").consts() == [5]


def test_library_state_stored_on_an_object_is_loaded_back(analyse):
    a = analyse({"m.py": """
        import rclpy
        from rclpy.node import Node
        class Talker(Node):
            def __init__(self):
                super().__init__('talker')
                self.status_topic = self.get_name() + '/status'
                self.declare_parameter('rate', 2.0)
                self.period = 1.0 / self.get_parameter('rate').value
        node = Talker()
        topic = node.status_topic
        period = node.period
        plain = rclpy.create_node('plain').get_name()
    """})
    assert a.strings("m", "topic") == ["talker/status"]
    assert a.value("m", "period").consts() == [0.5]
    assert a.strings("m", "plain") == ["plain"]


def test_a_factory_called_twice_makes_two_objects(analyse):
    a = analyse({"m.py": """
        class Box:
            pass
        def make(label):
            box = Box()
            box.label = label
            return box
        first = make('a')
        second = make('b')
        first_label = first.label
        second_label = second.label
    """})
    assert a.strings("m", "first_label") == ["a"]
    assert a.strings("m", "second_label") == ["b"]


def test_a_for_loop_inside_a_function_iterates_its_elements(analyse):
    # The loop's iterable lives in a CFG temporary: it is a local of the function, not a global.
    a = analyse({"m.py": """
        def f():
            global last
            for name in ('x', 'y'):
                last = name
        f()
    """})
    assert sorted(a.strings("m", "last")) == ["x", "y"]


def test_generated_message_classes_know_their_module_and_name(analyse):
    """rosidl names the module of ``nav_msgs.msg.Path`` ``nav_msgs.msg._path``: dispatch on it is decided."""
    a = analyse({"m.py": """
        from nav_msgs.msg import Path
        from sensor_msgs import msg as sensors
        from std_srvs.srv import SetBool

        plan = Path()
        module = plan.__module__
        name = type(plan).__name__
        via_class = plan.__class__.__name__
        cloud = sensors.PointCloud2.__module__
        response = SetBool.Response.__name__
        is_image = plan.__module__ == 'sensor_msgs.msg._image'
        listed = plan.__module__ in ('nav_msgs.msg._path', 'nav_msgs.msg._Path')
        not_listed = plan.__module__ not in ['sensor_msgs.msg._image']
        import os
        unknown_class = os.path.__module__
    """})
    assert a.strings("m", "module") == ["nav_msgs.msg._path"]
    assert a.strings("m", "name") == ["Path"]
    assert a.strings("m", "via_class") == ["Path"]
    assert a.strings("m", "cloud") == ["sensor_msgs.msg._point_cloud2"]
    assert a.strings("m", "response") == ["SetBool_Response"]
    assert a.value("m", "is_image").consts() == [False]
    assert a.value("m", "listed").consts() == [True]
    assert a.value("m", "not_listed").consts() == [True]
    assert a.value("m", "unknown_class").strings() is None  # not a generated class: not invented


def test_membership_in_a_tuple_is_decided_only_for_known_items(analyse):
    a = analyse({"m.py": """
        import os
        mode = 'fast' if os.environ.get('X') else 'slow'
        some = mode in ('fast', 'slow')
        none = mode in ('off', 'idle')
        maybe = mode in ('fast', 'off')
        open_ended = mode in ('off', os.environ.get('Y'))
    """})
    assert a.value("m", "some").consts() == [True]
    assert a.value("m", "none").consts() == [False]
    assert sorted(a.value("m", "maybe").consts()) == [False, True]
    assert sorted(a.value("m", "open_ended").consts()) == [False, True]


def test_an_unknown_joined_with_constants_keeps_them_as_hints_only(analyse):
    """``env or default``, an if/else and a loop: the constants survive as hints of ⊤; no
    branch is decided on them, and only text is built from them (``topic + '/filtered'`` may be
    ``/scan/filtered``, itself only a hint)."""
    a = analyse({"m.py": """
        import os

        topic = os.environ.get('TOPIC') or '/scan'
        if os.environ.get('SIM'):
            frame = 'sim_base'
        else:
            frame = os.environ['FRAME']
        suffixed = topic + '/filtered'
        default_topic = topic == '/scan'
        if topic == '/scan':
            picked = 'default'
        else:
            picked = 'custom'
        label = os.environ['A'] if os.environ.get('B') else os.environ['C']
    """})
    assert a.value("m", "topic").is_top and a.value("m", "topic").hinted() == ["/scan"]
    assert a.value("m", "frame").hinted() == ["sim_base"]
    assert a.value("m", "suffixed").is_top and a.value("m", "suffixed").hinted() == ["/scan/filtered"]
    assert sorted(a.value("m", "default_topic").consts()) == [False, True]
    assert a.strings("m", "picked") == ["custom", "default"]
    assert a.value("m", "label") == TOP
