"""Hypothesis strategies for small, syntactically valid, rclpy-flavoured Python programs.

The programs are not meant to be sensible ROS code: they combine the things
the analyser has to follow (string building, helpers, loops, recursion,
branches, exceptions, class hierarchies, callbacks) with the calls the rclpy
stubs model, in random order and nesting, so that every transfer function and
library model meets values it was not written for.
"""
from __future__ import annotations

from hypothesis import strategies as st

NAME_LITERALS = ["chatter", "/abs/topic", "~/private", "ns/x", "", "bad name", "{node}/sub", "1digit",
                 "a//b", "trailing/", "é", "x" * 300]
VARIABLES = ["name", "topic", "prefix", "count", "items", "flag"]
MSG_TYPES = ["String", "Int32", "AddTwoInts", "Fibonacci", "undefined_type", "None"]

HEADER = """\
import sys
import rclpy
from rclpy.node import Node
from rclpy.action import ActionServer, ActionClient
from rclpy.qos import QoSProfile, ReliabilityPolicy
from std_msgs.msg import String, Int32
from example_interfaces.srv import AddTwoInts
from example_interfaces.action import Fibonacci
"""


def _indent(lines: list[str], by: int = 4) -> list[str]:
    return [" " * by + line if line else line for line in lines]


@st.composite
def expressions(draw, depth: int = 2, names: tuple[str, ...] = ()) -> str:
    """A string-ish expression: literals, variables, concatenation, formatting, calls, conditionals."""
    leaves = [st.sampled_from(NAME_LITERALS).map(repr),
              st.integers(-3, 10**6).map(str),
              st.just("sys.argv[1]"),
              st.just("__name__")]
    if names:
        leaves.append(st.sampled_from(names))
    if depth <= 0:
        return draw(st.one_of(leaves))
    sub = expressions(depth - 1, names)
    return draw(st.one_of(
        *leaves,
        st.tuples(sub, sub).map(lambda p: f"{p[0]} + {p[1]}"),
        st.sampled_from(names or ("__name__",)).map(lambda n: f"f'{{{n}}}_x'"),
        st.tuples(sub, sub).map(lambda p: f"'%s/%s' % ({p[0]}, {p[1]})"),
        sub.map(lambda e: f"'{{}}/y'.format({e})"),
        sub.map(lambda e: f"str({e}).upper()"),
        sub.map(lambda e: f"str({e}) * 3"),
        st.tuples(sub, sub).map(lambda p: f"({p[0]} if flag else {p[1]})"),
        st.tuples(st.integers(0, 2), sub).map(lambda p: f"helper_{p[0]}({p[1]})"),
        sub.map(lambda e: f"[{e}, {e}][0]"),
        sub.map(lambda e: f"{{'k': {e}}}['k']"),
    ))


@st.composite
def ros_calls(draw, receiver: str, names: tuple[str, ...]) -> str:
    """One call of a modelled rclpy API on ``receiver`` with random (often wrong) arguments."""
    name = draw(expressions(2, names))
    msg = draw(st.sampled_from(MSG_TYPES))
    qos = draw(st.sampled_from(["10", "QoSProfile(depth=5)",
                                "QoSProfile(depth=1, reliability=ReliabilityPolicy.BEST_EFFORT)", name]))
    callback = draw(st.sampled_from(["print", "lambda *a: None", f"{receiver}.on_msg"
                                     if receiver == "self" else "print", "None", "helper_0"]))
    return draw(st.sampled_from([
        f"{receiver}.create_publisher({msg}, {name}, {qos})",
        f"{receiver}.create_subscription({msg}, {name}, {callback}, {qos})",
        f"{receiver}.create_service({msg}, {name}, {callback})",
        f"{receiver}.create_client({msg}, {name})",
        f"{receiver}.create_timer({draw(st.sampled_from(['0.1', '0', '-1', name]))}, {callback})",
        f"{receiver}.declare_parameter({name}, {name})",
        f"ActionServer({receiver}, {msg}, {name}, {callback})",
        f"ActionClient({receiver}, {msg}, {name})",
        f"rclpy.create_node({name}, namespace={draw(expressions(1, names))})",
    ]))


@st.composite
def blocks(draw, depth: int, receiver: str, names: tuple[str, ...], in_loop: bool = False,
           in_function: bool = True) -> list[str]:
    """A non-empty list of statement lines (already indented relative to the block)."""
    lines: list[str] = []
    for _ in range(draw(st.integers(1, 4))):
        kinds = ["assign", "call", "call"]
        if depth > 0:
            kinds += ["if", "while", "for", "try"]
        if in_loop:
            kinds.append("break")
        if in_function:
            kinds.append("return")
        kind = draw(st.sampled_from(kinds))
        if kind == "assign":
            lines.append(f"{draw(st.sampled_from(VARIABLES))} = {draw(expressions(2, names))}")
        elif kind == "call":
            lines.append(draw(ros_calls(receiver, names)))
        elif kind == "break":
            lines.append("break")
        elif kind == "return":
            lines.append(f"return {draw(expressions(1, names))}")
        else:
            inner = blocks(depth - 1, receiver, names, in_loop or kind in ("while", "for"), in_function)
            body = _indent(draw(inner))
            if kind == "if":
                lines += [f"if {draw(expressions(1, names))}:", *body, "else:", *_indent(draw(inner))]
            elif kind == "while":
                lines += [f"while {draw(st.sampled_from(['True', 'flag', 'count']))}:", *body]
            elif kind == "for":
                lines += [f"for item in {draw(st.sampled_from(['range(10**9)', 'items', '[1, 2]', 'name']))}:",
                          *body]
            else:
                lines += ["try:", *body, "except Exception:", *_indent(draw(inner))]
    return lines


@st.composite
def programs(draw) -> str:
    """A whole module: helpers (some recursive), Node subclasses, a main creating nodes."""
    names = tuple(VARIABLES) + ("arg",)
    out = [HEADER, "flag = len(sys.argv) > 2", "count = 0", "items = []", "name = topic = prefix = 'p'", ""]
    for index in range(3):
        body = draw(blocks(2, "node", names))
        recursion = draw(st.sampled_from(["", f"    helper_{index}(arg + 'r')",
                                          f"    helper_{(index + 1) % 3}([arg])"]))
        out += [f"def helper_{index}(arg, node=None):", "    node = node or rclpy.create_node('h')",
                *_indent(body), *( [recursion] if recursion else []), f"    return {draw(expressions(1, names))}", ""]
    classes = draw(st.integers(1, 3))
    for index in range(classes):
        base = draw(st.sampled_from(["Node"] + [f"Gen{j}" for j in range(index)]))
        init = draw(blocks(2, "self", names))
        callback = draw(blocks(1, "self", names))
        out += [f"class Gen{index}({base}):",
                "    def __init__(self, arg='x'):",
                f"        super().__init__({draw(expressions(1, names))})",
                *_indent(init, 8),
                "",
                "    def on_msg(self, msg):",
                *_indent(callback, 8),
                ""]
    main_body = draw(blocks(2, "node", names, in_function=True))
    made = [f"    node = Gen{draw(st.integers(0, classes - 1))}({draw(expressions(1, names))})"
            for _ in range(draw(st.integers(1, 3)))]
    out += ["def main(arg='m'):", "    rclpy.init()", *made, *_indent(main_body), "    rclpy.spin(node)", ""]
    if draw(st.booleans()):
        out += ["if __name__ == '__main__':", "    main()", ""]
    return "\n".join(out)
