"""The .msg/.srv/.action grammar: types, arrays, bounds, constants, defaults, comments, parts."""
import pytest

from flake8_rosgraph.interfaces.definitions import (FieldType, InterfaceError, parse_interface,
                                                    parse_message, parse_type)


@pytest.mark.parametrize("text, expected", [
    ("int32", FieldType("int32")),
    ("float64[]", FieldType("float64", "unbounded")),
    ("uint8[16]", FieldType("uint8", "fixed", 16)),
    ("Point[<=3]", FieldType("robot_msgs/msg/Point", "bounded", 3)),
    ("string<=10", FieldType("string", string_bound=10)),
    ("string<=5[<=2]", FieldType("string", "bounded", 2, 5)),
    ("geometry_msgs/Pose", FieldType("geometry_msgs/msg/Pose")),
    ("Header", FieldType("std_msgs/msg/Header")),
    ("builtin_interfaces/Time[2]", FieldType("builtin_interfaces/msg/Time", "fixed", 2)),
])
def test_types(text, expected):
    assert parse_type(text, "robot_msgs") == expected


@pytest.mark.parametrize("text", ["int32[<=]", "float64<=3", "9lives", "a/b/c", "int32[x]"])
def test_bad_types(text):
    with pytest.raises(InterfaceError):
        parse_type(text, "robot_msgs")


def test_fields_constants_defaults_and_comments():
    definition = parse_message(
        "# A status line.\n"
        "uint8 OK = 0   # fine\n"
        "uint8 ERROR=1\n"
        "string NAME=\"a # not a comment\"\n"
        "\n"
        "uint8\tlevel 0  # default zero\n"
        "Header header\n"
        "float64[9] covariance [0, 0, 0, 0, 0, 0, 0, 0, 0]\n",
        "robot_msgs/msg/Status")
    assert [f.name for f in definition.fields] == ["level", "header", "covariance"]
    assert definition.constants == ("OK", "ERROR", "NAME")
    assert definition.field("header").type.base == "std_msgs/msg/Header"
    assert definition.field("covariance").type == FieldType("float64", "fixed", 9)
    assert definition.field("missing") is None


def test_canonical_lines_read_back_to_the_same_definition():
    original = parse_message("Header header\nuint8 A=1\nstring<=3[<=4] tags\nPoint[] pts\n",
                             "robot_msgs/msg/Scan")
    again = parse_message("\n".join(original.lines()), original.key)
    assert again == original
    assert original.lines() == ["std_msgs/Header header", "string<=3[<=4] tags",
                                "robot_msgs/Point[] pts", "constant A"]


def test_service_and_action_parts():
    request, response = parse_interface("int64 a\nint64 b\n---\nint64 sum\n",
                                        "robot_msgs", "srv", "Add")
    assert (request.key, response.key) == ("robot_msgs/srv/Add_Request", "robot_msgs/srv/Add_Response")
    assert [f.name for f in response.fields] == ["sum"]
    goal, result, feedback = parse_interface("int32 order\n---\nint32[] sequence\n---\n",
                                             "robot_msgs", "action", "Count")
    assert feedback.key == "robot_msgs/action/Count_Feedback" and feedback.fields == ()
    empty_response = parse_interface("bool flag\n", "robot_msgs", "srv", "Set")[1]
    assert empty_response.fields == ()


def test_a_bad_line_names_interface_and_line():
    with pytest.raises(InterfaceError, match=r"robot_msgs/msg/Bad line 2: bad field name"):
        parse_message("int32 ok\nint32 9bad\n", "robot_msgs/msg/Bad")
    with pytest.raises(InterfaceError, match="more than 2 parts"):
        parse_interface("---\n---\n", "robot_msgs", "srv", "Three")
