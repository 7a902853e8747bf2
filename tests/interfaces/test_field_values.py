"""What rclpy's generated setters accept, field type by value (rosidl_generator_py ``_msg.py.em``)."""
import pytest

from flake8_rosgraph.graph.messages import ValueShape
from flake8_rosgraph.interfaces.definitions import parse_type
from flake8_rosgraph.interfaces.field_values import rejection, without_none_alternative


def const(value):
    kind = {bool: "bool", int: "int", float: "float", str: "str", bytes: "bytes", type(None): "none"}
    return ValueShape(kind[type(value)], value)


def instance(cls, modelled=False):
    return ValueShape("instance", cls=cls, modelled=modelled)


def seq(*items, kind="list"):
    return ValueShape("sequence", kind, length=len(items) if kind == "tuple" else None,
                      items=tuple(const(i) for i in items))


ACCEPTED = [
    ("float64", const(1.0)), ("float64", const(float("inf"))), ("float32", const(1e30)),
    ("int32", const(5)), ("int32", const(True)), ("uint8", const(255)), ("int8", const(-128)),
    ("char", const(65)), ("uint64", const(2 ** 64 - 1)),
    ("bool", const(False)), ("string", const("x")), ("string<=3", const("abc")),
    ("wstring", const("ü")), ("byte", const(b"\x01")),
    ("std_msgs/Header", instance("std_msgs.msg.Header")),
    ("builtin_interfaces/Time", instance("builtin_interfaces.msg.Time")),
    ("float64[]", seq(1.0, 2.0)), ("float64[3]", seq(1.0, 2.0, 3.0, kind="tuple")),
    ("float64[3]", seq(1.0)),            # a list's length is not known (append)
    ("uint8[]", const(b"\x00\x01")), ("int32[<=2]", seq(1, 2, kind="tuple")),
    ("geometry_msgs/Point[]", ValueShape("sequence", "list", items=(instance("geometry_msgs.msg.Point"),))),
    # not judged: values of classes that are neither messages nor modelled
    ("std_msgs/Header", instance("mylib.Header")), ("float64", instance("numpy.float64")),
    ("float64", ValueShape("other")), ("float64[]", ValueShape("sequence", "list")),
    # a class of the same name from another package's msg module may be a re-export
    # (bosdyn_msgs.msg does `from bosdyn_api_msgs.msg import *`)
    ("bosdyn_api_msgs/RobotCommandFeedback", instance("bosdyn_msgs.msg.RobotCommandFeedback")),
]

REJECTED = [
    ("float64", const(1), "the int 1"), ("float32", const(True), "the bool True"),
    ("float32", const(1e39), "out of the float32 range"),
    ("int32", const(1.5), "the float 1.5"), ("int32", const("5"), "the str '5'"),
    ("uint8", const(300), "out of [0, 255]"), ("uint8", const(-1), "out of [0, 255]"),
    ("int8", const(128), "out of [-128, 127]"), ("char", const("a"), "the str 'a'"),
    ("bool", const(1), "the int 1"), ("string", const(3), "the int 3"), ("string", const(None), "None"),
    ("string<=3", const("abcd"), "longer than 3"), ("byte", const(1), "the int 1"),
    ("byte", const(b"ab"), "the bytes b'ab'"),
    ("builtin_interfaces/Time", instance("rclpy.time.Time", modelled=True), "a rclpy.time.Time"),
    ("std_msgs/Header", instance("geometry_msgs.msg.Pose"), "a geometry_msgs/msg/Pose message"),
    ("std_msgs/Header", const(0), "the int 0"), ("std_msgs/Header", seq(), "a list"),
    ("int32", instance("std_msgs.msg.Int32"), "a std_msgs/msg/Int32 message"),
    ("float32[]", const(0.0), "the float 0.0"), ("string[]", const("abc"), "the str 'abc'"),
    ("float64[]", seq(0, 1), "a sequence holding the int 0"),
    ("float64[2]", seq(1.0, 2.0, 3.0, kind="tuple"), "exactly 2"),
    ("int32[<=1]", seq(1, 2, kind="tuple"), "at most 1"),
    ("uint8[]", seq(256), "out of [0, 255]"),
    ("geometry_msgs/Point[]", instance("geometry_msgs.msg.Point"), "a geometry_msgs/msg/Point message"),
]


@pytest.mark.parametrize("spelled, shape", ACCEPTED)
def test_accepted(spelled, shape):
    assert rejection(parse_type(spelled, "test_msgs"), shape) is None


@pytest.mark.parametrize("spelled, shape, phrase", REJECTED)
def test_rejected(spelled, shape, phrase):
    why = rejection(parse_type(spelled, "test_msgs"), shape)
    assert why is not None and phrase in why


def test_none_is_judged_only_alone():
    assert without_none_alternative([const(None), instance("nav_msgs.msg.Path")]) == \
        [instance("nav_msgs.msg.Path")]
    assert without_none_alternative([const(None)]) == [const(None)]
