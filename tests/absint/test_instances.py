"""Facts about instances of unmodelled library classes (construct / set_attribute effects),
type tests decided by ``isinstance``, and one effect per receiver of a library method."""
from flake8_rosgraph.absint.values import Extern, Obj


def _arg(effect, name):
    return dict(effect.args)[name]


def test_construction_records_class_keywords_and_positionals(analyse):
    result = analyse({"m.py": """
        import sys
        from std_msgs.msg import String
        LABEL = 'hello'
        a = String(data=LABEL)
        b = String('x', 'y')
        c = String(*sys.argv)
    """})
    built = result.effects("construct")
    assert [e.line for e in built] == [5, 6, 7]
    first = built[0]
    assert _arg(first, "class").strings() == ["std_msgs.msg.String"]
    assert _arg(first, "kw:data").strings() == ["hello"]
    assert _arg(first, "positional").consts() == [0]
    assert _arg(built[1], "positional").consts() == [2]
    assert _arg(built[2], "star").consts() == [True]
    (obj,) = _arg(first, "object")
    assert obj == Obj("m.py:5:4", Extern("std_msgs.msg.String"))


def test_lower_case_calls_and_modelled_classes_record_nothing(analyse):
    result = analyse({"m.py": """
        import numpy as np
        from rclpy.qos import QoSProfile
        a = np.zeros(3)
        q = QoSProfile(depth=5)
    """})
    assert result.effects("construct") == []


def test_attribute_stores_follow_chains_the_analysis_did_not_model(analyse):
    result = analyse({"pkg/__init__.py": "", "pkg/build.py": """
        from sensor_msgs.msg import Image
        from std_msgs.msg import Header

        def stamped(frame):
            img = Image()
            img.header.stamp.sec = 5
            img.header.frame_id = frame
            img.height = 480
            return img

        def with_header():
            img = Image()
            img.header = Header()
            img.header.frame_id = 'cam'
            return img

        class Holder:
            def __init__(self):
                self.msg = Image()
                self.msg.width = 640

        FIRST = stamped('camera')
        SECOND = with_header()
        Holder()
    """})
    stores = {(e.line, _arg(e, "path").strings()[0], tuple(sorted(a.cls.qualname for a in _arg(e, "object"))))
              for e in result.effects("set_attribute")}
    assert stores == {
        (7, "header.stamp.sec", ("sensor_msgs.msg.Image",)),
        (8, "header.frame_id", ("sensor_msgs.msg.Image",)),
        (9, "height", ("sensor_msgs.msg.Image",)),
        (14, "header", ("sensor_msgs.msg.Image",)),
        # Once the workspace stored a Header there, the chain starts at that Header.
        (15, "frame_id", ("std_msgs.msg.Header",)),
        (21, "width", ("sensor_msgs.msg.Image",)),
    }
    frames = [_arg(e, "value").strings() for e in result.effects("set_attribute") if e.line == 8]
    assert ["camera"] in frames


def test_attribute_reads_are_recorded_from_the_nearest_instance(analyse):
    result = analyse({"m.py": """
        from sensor_msgs.msg import Image
        img = Image()
        SEC = img.header.stamp.sec
        img.data.append(1)
        WIDTH = img.width
    """})
    reads = sorted((e.line, _arg(e, "path").strings()[0]) for e in result.effects("get_attribute"))
    assert reads == [(4, "header"), (4, "header.stamp"), (4, "header.stamp.sec"),
                     (5, "data"), (5, "data.append"), (6, "width")]


def test_chains_through_calls_are_not_evaluated_twice(analyse):
    result = analyse({"m.py": """
        from std_msgs.msg import Header
        def make():
            return Header()
        make().stamp.sec = 1
    """})
    assert result.effects("set_attribute") == []


def test_unstored_attribute_of_a_library_instance_is_unknown(analyse):
    # 'path' is stored on another object: reading it from a fresh library instance is the
    # library's default, not "nothing".
    result = analyse({"m.py": """
        from nav_msgs.msg import Path
        from nav2_msgs.action import ComputePathToPose
        goal = Path()
        goal.path = 1
        RESULT = ComputePathToPose.Result().path
    """})
    assert result.value("m", "RESULT").is_top


def test_isinstance_decides_branches_by_exact_types(analyse):
    result = analyse({"m.py": """
        from geometry_msgs.msg import PoseStamped

        def pick(start):
            if isinstance(start, int):
                return 'id'
            elif isinstance(start, (PoseStamped, float)):
                return 'pose'
            return 'other'

        BY_ID = pick(3)
        BY_POSE = pick(PoseStamped())
        BY_TEXT = pick('x')
        BY_BOOL = pick(True)
    """})
    assert result.strings("m", "BY_ID") == ["id"]
    assert result.strings("m", "BY_POSE") == ["pose"]
    assert result.strings("m", "BY_TEXT") == ["other"]
    assert result.strings("m", "BY_BOOL") == ["id"]  # bool is an int


def test_isinstance_stays_undecided_when_values_disagree_or_are_unknown(analyse):
    result = analyse({"m.py": """
        import sys
        from mylib import Thing
        def kind(v):
            return 'int' if isinstance(v, int) else 'no'
        MIXED = kind(1 if sys.argv else 'a')
        UNKNOWN = kind(sys.argv[1])
        USER = kind(Thing())
        OTHER_CLASS = 'yes' if isinstance(Thing(), Thing) else 'no'
    """})
    assert result.strings("m", "MIXED") == ["int", "no"]
    assert result.strings("m", "UNKNOWN") == ["int", "no"]
    assert result.strings("m", "USER") == ["no"]
    assert result.strings("m", "OTHER_CLASS") == ["yes"]


def test_publish_on_either_of_two_publishers_records_both(analyse):
    result = analyse({"m.py": """
        import rclpy
        from geometry_msgs.msg import Twist, TwistStamped
        node = rclpy.create_node('n')
        stamped = node.declare_parameter('stamped', False).value
        if stamped:
            pub = node.create_publisher(TwistStamped, 'cmd', 10)
        else:
            pub = node.create_publisher(Twist, 'cmd', 10)
        pub.publish(Twist())
    """})
    types = sorted(a.qualname for e in result.effects("publish") for a in _arg(e, "type"))
    assert types == ["geometry_msgs.msg.Twist", "geometry_msgs.msg.TwistStamped"]
    assert all(isinstance(a, Obj) for e in result.effects("publish") for a in _arg(e, "msg"))


def test_clock_now_is_an_rclpy_time_and_to_msg_a_message(analyse):
    result = analyse({"m.py": """
        import rclpy
        node = rclpy.create_node('n')
        NOW = node.get_clock().now()
        STAMP = NOW.to_msg()
    """})
    assert [a.cls for a in result.value("m", "NOW")] == [Extern("rclpy.time.Time")]
    assert [a.cls for a in result.value("m", "STAMP")] == [Extern("builtin_interfaces.msg.Time")]
