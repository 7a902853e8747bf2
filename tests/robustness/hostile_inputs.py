"""Generator of hostile workspace files, and the good files they are mixed with.

Each :class:`Hostile` case is a few files (bytes, written at test time — the big
and deep ones are generated here, never committed) placed next to
:data:`GOOD_FILES`, two ordinary rclpy nodes. Whatever a case does, the good
nodes' entities must all still be extracted; a case that cannot be analysed
must say so in a diagnostic naming its file. Files meant to be analysed import
``rclpy``: the analyser only starts from modules that reach a modelled library.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import Mapping

GOOD_TALKER = """\
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class GoodTalker(Node):
    def __init__(self):
        super().__init__('good_talker')
        self.pub = self.create_publisher(String, 'good_chatter', 10)
        self.echo = self.create_subscription(String, 'good_echo', self.on_echo, 10)
        self.loop = self.create_publisher(String, 'good_echo', 10)
        self.timer = self.create_timer(0.5, self.tick)

    def on_echo(self, msg):
        self.pub.publish(msg)

    def tick(self):
        self.pub.publish(String())


def main():
    rclpy.init()
    rclpy.spin(GoodTalker())
"""

GOOD_LISTENER = """\
import rclpy
from rclpy.node import Node
from std_msgs.msg import Int32


class GoodListener(Node):
    def __init__(self):
        super().__init__('good_listener')
        self.sub = self.create_subscription(Int32, 'good_chatter', self.on_msg, 10)

    def on_msg(self, msg):
        self.get_logger().info(str(msg.data))


def main():
    rclpy.init()
    rclpy.spin(GoodListener())
"""

GOOD_FILES: dict[str, str] = {"good_talker.py": GOOD_TALKER, "good_listener.py": GOOD_LISTENER}


def line_of(text: str, fragment: str) -> int:
    """1-based number of the first line of ``text`` containing ``fragment``."""
    for number, line in enumerate(text.splitlines(), 1):
        if fragment in line:
            return number
    raise ValueError(f"{fragment!r} not in text")


#: ``(node fqn, kind, name or period, path, line)`` of everything the good files create.
GOOD_ENTITIES: frozenset[tuple[str, str, object, str, int]] = frozenset({
    ("/good_talker", "node", "good_talker", "good_talker.py", line_of(GOOD_TALKER, "super().__init__")),
    ("/good_talker", "publishers", "/good_chatter", "good_talker.py", line_of(GOOD_TALKER, "'good_chatter'")),
    ("/good_talker", "subscriptions", "/good_echo", "good_talker.py",
     line_of(GOOD_TALKER, "create_subscription(String, 'good_echo'")),
    ("/good_talker", "publishers", "/good_echo", "good_talker.py",
     line_of(GOOD_TALKER, "create_publisher(String, 'good_echo'")),
    ("/good_talker", "timers", 0.5, "good_talker.py", line_of(GOOD_TALKER, "create_timer")),
    ("/good_listener", "node", "good_listener", "good_listener.py", line_of(GOOD_LISTENER, "super().__init__")),
    ("/good_listener", "subscriptions", "/good_chatter", "good_listener.py",
     line_of(GOOD_LISTENER, "create_subscription")),
})

#: ``(path:line:, code)`` pairs flake8 must report for the good files (a type clash and a self-loop).
GOOD_FLAKE8_FINDINGS: tuple[tuple[str, str], ...] = (
    (f"good_listener.py:{line_of(GOOD_LISTENER, 'create_subscription')}:", "ROS004"),
    (f"good_talker.py:{line_of(GOOD_TALKER, 'create_subscription')}:", "ROS002"),
)

#: What an unparsable / too-deep file's diagnostic may say, across Python 3.10–3.13.
TOO_DEEP = r"syntax error|cannot parse|nested too deeply|too complex|parenthes|indentation|recursion"


@dataclass(frozen=True)
class Hostile:
    """One hostile input: files to add to the good workspace and what must come out of it.

    ``diagnostic`` is a regular expression for the message of a diagnostic on
    ``path``: with ``required`` one such diagnostic must exist; without, the
    outcome depends on the Python version (e.g. whether ``ast.parse`` copes), so
    only the diagnostics present on ``path`` must match it; ``None`` asks for
    nothing beyond the checks every run gets. ``entities`` are
    ``(fqn, kind, name, path, line)`` the hostile files themselves must still yield.
    """

    name: str
    files: Mapping[str, bytes]
    diagnostic: str | None = None
    required: bool = True
    path: str = "bad.py"
    entities: frozenset = field(default_factory=frozenset)

    def write(self, root: Path) -> None:
        write_files(root, {**{k: v.encode() for k, v in GOOD_FILES.items()}, **self.files})


def write_files(root: Path, files: Mapping[str, bytes]) -> None:
    for rel, content in files.items():
        target = root / rel
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(content)


def _py(text: str) -> bytes:
    return text.encode("utf-8")


def _node_module(node: str, topic: str, newline: str = "\n") -> str:
    """A module creating node ``node`` with one publisher on ``topic`` at its line 4."""
    return newline.join([
        "import rclpy",
        "from std_msgs.msg import String",
        f"node = rclpy.create_node('{node}')",
        f"node.create_publisher(String, '{topic}', 10)",
        "",
    ])


def _node_entities(node: str, topic: str, path: str, first_line: int) -> frozenset:
    """Entities of :func:`_node_module` placed at ``first_line`` of ``path``."""
    return frozenset({(f"/{node}", "node", node, path, first_line + 2),
                      (f"/{node}", "publishers", f"/{topic}", path, first_line + 3)})


# -- deeply nested source ----------------------------------------------------------------------

def _indented(lines: list[str], depth: int) -> str:
    return "".join(" " * depth + line + "\n" for line in lines)


def nested_parentheses(depth: int) -> str:
    return "import rclpy\nx = " + "(" * depth + "1" + ")" * depth + "\n"


def nested_lists(depth: int) -> str:
    return "import rclpy\nx = " + "[" * depth + "]" * depth + "\n"


def nested_ifs(depth: int) -> str:
    return "import rclpy\nx = 1\n" + "".join(" " * i + "if x:\n" for i in range(depth)) + " " * depth + "x\n"


def binop_chain(length: int) -> str:
    return "import rclpy\na = 'a'\nx = " + " + ".join(["a"] * length) + "\n"


def method_chain(length: int) -> str:
    return "import rclpy\nx = rclpy" + ".f()" * length + "\n"


def not_chain(length: int) -> str:
    return "import rclpy\nx = " + "not " * length + "rclpy\n"


def elif_chain(length: int, in_function: bool) -> str:
    lines = ["if a == 0:", "    pass"] + [part for i in range(1, length + 1)
                                           for part in (f"elif a == {i}:", "    pass")]
    if not in_function:
        return "import rclpy\na = 3\n" + _indented(lines, 0)
    return "import rclpy\n\n\ndef pick(a):\n" + _indented(lines, 4) + "\n\npick(3)\n"


def nested_functions(depth: int) -> str:
    """``def`` inside ``def`` as deep as Python's indentation limit allows, each calling the next."""
    out = ["import rclpy"]
    for level in range(depth):
        out.append(" " * level + f"def f{level}(x):")
    out.append(" " * depth + "return rclpy.create_node(x)")
    for level in reversed(range(1, depth)):
        out.append(" " * level + f"return f{level}(x + '_')")
    out.append("f0('deep')")
    return "\n".join(out) + "\n"


def nested_lambdas(depth: int) -> str:
    return "import rclpy\nf = " + "lambda: " * depth + "rclpy\ng = f" + "()" * depth + "\n"


# -- big files ---------------------------------------------------------------------------------

def long_file(lines: int) -> tuple[bytes, frozenset]:
    """``lines`` lines of assignments, then a node: the analyser must read to the very end."""
    body = "".join(f"value_{i} = {i} * 2 + len('{i}')\n" for i in range(lines))
    text = "import rclpy\n" + body + _node_module("long_file_node", "long_file_topic")
    return _py(text), _node_entities("long_file_node", "long_file_topic", "bad.py", lines + 2)


def huge_string(size: int) -> tuple[bytes, frozenset]:
    """A ``size``-character string literal, then a node."""
    text = "import rclpy\nBLOB = '" + "x" * size + "'\nSIZE = len(BLOB)\n" + _node_module("after_blob", "after_blob")
    return _py(text), _node_entities("after_blob", "after_blob", "bad.py", 4)


# -- analyser stress: values that never stop changing, recursion, dynamic Python ----------------

GROWING_LOOPS = """\
import rclpy
from std_msgs.msg import String

node = rclpy.create_node('loop_node')
name = 'grow'
while True:
    name = name + '_x'
    node.create_publisher(String, name, 10)
    if len(name) > 10 ** 9:
        break

count = 0
while True:
    count += 1
    node.create_subscription(String, f'count_{count}', print, 10)

nest = []
while True:
    nest = [nest, nest]

table = {}
while True:
    table = {'k': table, str(len(table)): (table,)}

doubling = 'ab'
for _ in range(10 ** 12):
    doubling = doubling + doubling
    node.declare_parameter(doubling, doubling)

chain = ()
while chain != 1:
    chain = (chain, chain + (1,))
"""

RECURSION = """\
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


def grow(text):
    return grow(text + 'a') + [text]


def ping(value):
    return pong([value])


def pong(value):
    return ping((value, value))


class Chain(Node):
    def __init__(self, depth):
        super().__init__('chain_' + str(depth))
        self.create_publisher(String, 'chain_' + str(depth), 10)
        self.next = Chain(depth + 1)


class Walker:
    def __init__(self):
        self.twin = Walker()

    def step(self, path):
        return self.step(path + '/x').step(path)


def forever(*args, **kwargs):
    return forever(*args, args, **kwargs, **{str(len(kwargs)): kwargs})


grow('')
ping(0)
Chain(0)
Walker().step('')
forever()
"""

DYNAMIC_PYTHON = """\
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Meta(type):
    def __new__(mcs, name, bases, namespace):
        return super().__new__(mcs, name, bases, namespace)

    def __call__(cls, *args, **kwargs):
        return cls


class Weird(Node, metaclass=Meta):
    def __init__(self):
        super().__init__('weird_' + type(self).__name__)


class Loop(Weird, metaclass=Meta):
    def __getattr__(self, name):
        return getattr(self, name + '_again')


exec('import os; os.remove("nothing")')
eval(compile('1 + 1', '<hostile>', 'eval'))
setattr(Weird, 'create_publisher', None)
setattr(Loop, 'x' * 50, Loop)
getattr(rclpy, 'create_' + 'node')('dyn_' + str(len(dir())))
globals()['Node'] = object
vars()[chr(110)] = Loop()
Loop().anything.at.all
type('Made', (Weird,), {'__init__': lambda self: None})()
"""

MONKEYPATCH_RCLPY = """\
import rclpy
import rclpy.node
from rclpy.node import Node
import std_msgs.msg

rclpy.node.Node.create_publisher = lambda self, *args, **kwargs: None
Node.create_subscription = print
rclpy.create_node = None
rclpy.init = rclpy.shutdown
std_msgs.msg.String = int
rclpy.node.Node = object
del rclpy.node
"""

STAR_A = """\
import rclpy
from star_b import *
from rclpy.node import *
from os.path import *
NAME_A = 'a' + NAME_B
"""
STAR_B = """\
from star_a import *
from no_such_module_anywhere import *
NAME_B = 'b' + NAME_A
"""

CYCLE_A = """\
import rclpy
import cycle_b
from cycle_b import helper
NAME = cycle_b.NAME + '_a'
node = rclpy.create_node(helper())
"""
CYCLE_B = """\
import cycle_a
from cycle_a import NAME as OTHER
NAME = 'b'


def helper():
    return cycle_a.NAME + OTHER
"""
CYCLE_PKG_INIT = "from .mod import *\nfrom . import mod\nimport cyclepkg.mod\n"
CYCLE_PKG_MOD = "import rclpy\nfrom . import *\nfrom cyclepkg import mod as me\nfrom .mod import *\nVALUE = me.VALUE\n"

BOM_NODE = "\ufeff" + _node_module("bom_node", "bom_topic")
LATIN1 = ("# -*- coding: latin-1 -*-\n" + _node_module("latin_node", "latin_topic")
          + "LABEL = 'caf\xe9'\n").encode("latin-1")


@lru_cache(maxsize=None)
def hostile_cases() -> tuple[Hostile, ...]:
    """Every hostile workspace input (big and deep ones generated here, once per test session)."""
    long_bytes, long_entities = long_file(20_000)
    blob_bytes, blob_entities = huge_string(3 * 1024 * 1024)
    return (
        # -- files that cannot be read as Python --------------------------------------------------
        Hostile("syntax_error", {"bad.py": b"import rclpy\ndef broken(:\n    pass\n"}, r"^syntax error"),
        Hostile("unterminated_string", {"bad.py": b"import rclpy\nx = '''never closed\n"}, r"^syntax error"),
        Hostile("tabs_and_spaces", {"bad.py": b"import rclpy\nif 1:\n\tx = 1\n        y = 2\n"},
                r"^syntax error"),
        Hostile("python2_print", {"bad.py": b"import rclpy\nprint 'hello'\n"}, r"^syntax error"),
        Hostile("null_bytes", {"bad.py": b"import rclpy\nx = 1\x00\n"}, r"null byte"),
        Hostile("huge_int_literal", {"bad.py": _py("import rclpy\nx = 1" + "0" * 5000 + "\n")},
                r"syntax error|cannot parse"),
        # -- encodings ------------------------------------------------------------------------------
        Hostile("invalid_utf8", {"bad.py": b"import rclpy\nx = '\xff\xfe\xc3('\n"}, r"^cannot decode"),
        Hostile("utf16_without_declaration", {"bad.py": "import rclpy\n".encode("utf-16")}, r"^cannot decode"),
        Hostile("unknown_codec", {"bad.py": b"# -*- coding: no-such-codec -*-\nimport rclpy\n"},
                r"^cannot decode.*no-such-codec"),
        Hostile("declared_ascii_with_utf8", {"bad.py": "# coding: ascii\nimport rclpy\nx = 'é'\n".encode()},
                r"^cannot decode"),
        Hostile("bom_and_latin1_declaration",
                {"bad.py": b"\xef\xbb\xbf# -*- coding: latin-1 -*-\nimport rclpy\n"}, r"^cannot decode"),
        Hostile("latin1_declared", {"bad.py": LATIN1}, None,
                entities=_node_entities("latin_node", "latin_topic", "bad.py", 2)),
        Hostile("utf8_bom", {"bad.py": BOM_NODE.encode("utf-8")}, None,
                entities=_node_entities("bom_node", "bom_topic", "bad.py", 1)),
        Hostile("crlf_line_ends", {"bad.py": _py(_node_module("crlf_node", "crlf_topic", "\r\n"))}, None,
                entities=_node_entities("crlf_node", "crlf_topic", "bad.py", 1)),
        Hostile("cr_line_ends", {"bad.py": _py(_node_module("cr_node", "cr_topic", "\r"))}, None,
                entities=_node_entities("cr_node", "cr_topic", "bad.py", 1)),
        Hostile("empty_file", {"bad.py": b""}, None),
        # -- size -----------------------------------------------------------------------------------
        Hostile("twenty_thousand_lines", {"bad.py": long_bytes}, None, entities=long_entities),
        Hostile("three_megabyte_string", {"bad.py": blob_bytes}, None, entities=blob_entities),
        Hostile("over_size_limit", {"bad.py": _py("import rclpy\n" + "# padding\n" * 500_000)},
                r"larger than"),
        # -- nesting beyond what the parser or a recursive visitor can take --------------------------
        Hostile("nested_parentheses_5000", {"bad.py": _py(nested_parentheses(5000))}, TOO_DEEP),
        Hostile("nested_lists_5000", {"bad.py": _py(nested_lists(5000))}, TOO_DEEP),
        Hostile("nested_ifs_99", {"bad.py": _py(nested_ifs(99))}, TOO_DEEP, required=False),
        Hostile("nested_ifs_150", {"bad.py": _py(nested_ifs(150))}, TOO_DEEP),
        Hostile("binop_chain_5000", {"bad.py": _py(binop_chain(5000))}, TOO_DEEP),
        Hostile("binop_chain_900", {"bad.py": _py(binop_chain(900))}, TOO_DEEP, required=False),
        Hostile("not_chain_5000", {"bad.py": _py(not_chain(5000))}, TOO_DEEP),
        Hostile("method_chain_3000", {"bad.py": _py(method_chain(3000))}, TOO_DEEP),
        Hostile("method_chain_100000", {"bad.py": _py(method_chain(100_000))}, TOO_DEEP),
        Hostile("elif_chain_1000_module", {"bad.py": _py(elif_chain(1000, in_function=False))}, TOO_DEEP,
                required=False),
        Hostile("elif_chain_1000_function", {"bad.py": _py(elif_chain(1000, in_function=True))}, TOO_DEEP,
                required=False),
        Hostile("nested_functions_99", {"bad.py": _py(nested_functions(99))}, TOO_DEEP, required=False),
        Hostile("nested_lambdas_900", {"bad.py": _py(nested_lambdas(900))}, TOO_DEEP, required=False),
        # -- code the analyser must not loop on or drown in -----------------------------------------
        Hostile("growing_loops", {"bad.py": _py(GROWING_LOOPS)}, None),
        Hostile("recursion", {"bad.py": _py(RECURSION)}, None),
        Hostile("dynamic_python", {"bad.py": _py(DYNAMIC_PYTHON)}, None),
        Hostile("monkeypatched_rclpy", {"bad.py": _py(MONKEYPATCH_RCLPY)}, None),
        Hostile("star_import_cycle", {"star_a.py": _py(STAR_A), "star_b.py": _py(STAR_B)}, None,
                path="star_a.py"),
        Hostile("circular_imports", {"cycle_a.py": _py(CYCLE_A), "cycle_b.py": _py(CYCLE_B),
                                     "cyclepkg/__init__.py": _py(CYCLE_PKG_INIT),
                                     "cyclepkg/mod.py": _py(CYCLE_PKG_MOD)}, None, path="cycle_a.py"),
    )


def hostile_case(name: str) -> Hostile:
    return next(case for case in hostile_cases() if case.name == name)
