"""The strings a C++ name is built from, as far as one file tells.

Deliberately simple and flow-insensitive: a variable's value is the union of
everything assigned to it in its function (a local), in the file's member
functions, field defaults and constructor initialisers (a member), at
namespace scope (a constant) or by an object-like ``#define`` of one string.
Followed: string literals and their concatenation (``+``, adjacent literals),
``std::string(...)``, ``.c_str()``, the ternary operator, and parameters —
``declare_parameter("p", "default")`` (any ``declare*parameter*`` call, typed
or not, ``rclcpp::ParameterValue`` unwrapped) is worth its default, and so are
``get_parameter("p").as_string()`` and ``get_parameter("p", out)``. Anything
else — a function parameter, a value from another file, a call not listed —
is unknown (``None``), and one unknown assignment makes the whole value unknown.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from itertools import product
from typing import Any

from .syntax import text

#: More possible strings than this is taken as unknown.
MAX_CHOICES = 16
#: How many bindings deep a value is followed.
MAX_DEPTH = 12
#: Methods that pass a string through (``s.c_str()``, ``get_parameter("p").as_string()``).
PASS_THROUGH = frozenset({"c_str", "data", "str", "as_string", "get_value", "get", "get_parameter_value"})
#: Constructors and wrappers whose single argument is the value.
WRAPPERS = frozenset({"string", "basic_string", "string_view", "ParameterValue"})

Key = tuple[int, int]


class _Unknown:
    def __repr__(self) -> str:
        return "UNKNOWN"


#: A binding whose value is not followed (a function parameter, ``declare_parameter`` without default).
UNKNOWN = _Unknown()


@dataclass(frozen=True)
class ParamRef:
    """The value of a parameter read back (``get_parameter("p", out)``): its declared defaults."""

    name: Any
    func: Any


@dataclass(frozen=True)
class CtorArg:
    """A constructor's parameter: argument ``index`` of every ``make_shared<cls>(...)`` of the file
    (its default value when a construction leaves it out)."""

    cls: str
    index: int
    default: Any = None


@dataclass(frozen=True)
class Binding:
    """One value given to a name: an expression (evaluated in ``func``), :class:`ParamRef` or :data:`UNKNOWN`."""

    value: Any
    func: Any = None


def is_syntax(value: Any) -> bool:
    """Whether a binding's value is an expression (not :data:`UNKNOWN`, :class:`ParamRef`, :class:`CtorArg`)."""
    return value is not None and not isinstance(value, (_Unknown, ParamRef, CtorArg))


def key(node: Any) -> Key:
    """A syntax node's identity within its file."""
    return (node.start_byte, node.end_byte)


def last_name(name: str) -> str:
    """``rclcpp::Node`` → ``Node``, ``Foo<T>`` → ``Foo``, ``std::make_shared<X>`` → ``make_shared``."""
    if "<" not in name:
        return name.replace(" ", "").rsplit("::", 1)[-1]
    depth = 0
    out = []
    for char in name:
        if char == "<":
            depth += 1
        elif char == ">":
            depth -= 1
        elif depth == 0:
            out.append(char)
    return "".join(out).replace(" ", "").rsplit("::", 1)[-1]


@dataclass
class FileIndex:
    """The bindings of one file, filled by :mod:`.extract` in one walk."""

    macros: dict[str, list[str]] = field(default_factory=dict)
    constants: dict[str, list[Binding]] = field(default_factory=dict)
    members: dict[str, list[Binding]] = field(default_factory=dict)
    locals: dict[Key, dict[str, list[Binding]]] = field(default_factory=dict)
    #: Names declared (or taken as parameters) in each function: their assignments stay local.
    local_names: dict[Key, set[str]] = field(default_factory=dict)
    #: Assignments by function, sorted into locals or members once the walk is over.
    assignments: dict[Key, dict[str, list[Binding]]] = field(default_factory=dict)
    parameter_defaults: dict[str, list[Binding]] = field(default_factory=dict)
    #: ``make_shared<Cls>(args)`` / ``make_unique`` of the file's classes: ``(arguments, function)``.
    constructions: dict[str, list[tuple[list[Any], Any]]] = field(default_factory=dict)

    def declare_local(self, func: Any, name: str, binding: Binding | None) -> None:
        self.local_names.setdefault(key(func), set()).add(name)
        if binding is not None:
            self.locals.setdefault(key(func), {}).setdefault(name, []).append(binding)

    def assign(self, func: Any, name: str, binding: Binding) -> None:
        if func is None:
            self.constants.setdefault(name, []).append(binding)
        else:
            self.assignments.setdefault(key(func), {}).setdefault(name, []).append(binding)

    def settle(self) -> None:
        """Sort each function's assignments: to its own locals, else to the class members."""
        for func_key, by_name in self.assignments.items():
            declared = self.local_names.get(func_key, set())
            for name, bindings in by_name.items():
                target = self.locals.setdefault(func_key, {}) if name in declared else self.members
                target.setdefault(name, []).extend(bindings)
        self.assignments.clear()

    def bindings(self, name: str, func: Any, member_only: bool = False) -> list[Binding] | None:
        """What ``name`` may hold where ``func`` reads it; ``None`` when nothing is known of it."""
        if not member_only and func is not None and name in self.local_names.get(key(func), ()):
            return self.locals.get(key(func), {}).get(name) or None
        if name in self.members:
            return self.members[name]
        if member_only:
            return None
        return self.constants.get(name)


class Evaluator:
    """Evaluates expressions of one file to the set of strings they may be (``None``: unknown)."""

    def __init__(self, index: FileIndex) -> None:
        self.index = index
        self._active: set[tuple[Key, str]] = set()
        #: Set when a value read since the last reset came from a parameter (overridable at launch).
        self.read_parameter = False

    def strings(self, node: Any, func: Any, depth: int = 0) -> frozenset[str] | None:
        if node is None or depth > MAX_DEPTH:
            return None
        kind = node.type
        if kind == "string_literal":
            return _literal(node)
        if kind == "raw_string_literal":
            content = [c for c in node.named_children if c.type == "raw_string_content"]
            return frozenset({text(content[0]) if content else ""})
        if kind == "concatenated_string":
            return self._product([self.strings(c, func, depth + 1) for c in node.named_children])
        if kind in ("parenthesized_expression", "argument_list", "initializer_list"):
            inner = [c for c in node.named_children if c.type != "comment"]
            return self.strings(inner[0], func, depth + 1) if len(inner) == 1 else None
        if kind == "compound_literal_expression":
            return self.strings(node.child_by_field_name("value"), func, depth + 1)
        if kind == "conditional_expression":
            return self._union([self.strings(node.child_by_field_name(f), func, depth + 1)
                                for f in ("consequence", "alternative")])
        if kind == "binary_expression" and text(node.child_by_field_name("operator")) == "+":
            return self._product([self.strings(node.child_by_field_name(f), func, depth + 1)
                                  for f in ("left", "right")])
        if kind == "identifier":
            return self.name(text(node), func, depth)
        if kind == "qualified_identifier":
            return self.name(last_name(text(node)), None, depth)
        if kind == "field_expression" and _is_this(node.child_by_field_name("argument")):
            return self.name(text(node.child_by_field_name("field")), func, depth, member_only=True)
        if kind == "call_expression":
            return self._call(node, func, depth)
        return None

    def name(self, name: str, func: Any, depth: int, member_only: bool = False) -> frozenset[str] | None:
        bindings = self.index.bindings(name, func, member_only)
        if bindings is None:
            macro = self.index.macros.get(name)
            return frozenset(macro) if macro and not member_only else None
        guard = (key(func) if func is not None else (-1, -1), name)
        if guard in self._active:  # x = x + "_suffix": a value that feeds itself is not followed
            return None
        self._active.add(guard)
        try:
            return self._union([self.binding(b, depth + 1) for b in bindings])
        finally:
            self._active.discard(guard)

    def binding(self, binding: Binding, depth: int) -> frozenset[str] | None:
        if binding.value is UNKNOWN:
            return None
        if isinstance(binding.value, ParamRef):
            return self.parameter(binding.value, depth)
        if isinstance(binding.value, CtorArg):
            return self.constructed(binding.value, binding.func, depth)
        return self.strings(binding.value, binding.func, depth)

    def constructed(self, arg: CtorArg, ctor: Any, depth: int) -> frozenset[str] | None:
        """What a constructor parameter is given by the file's constructions (none: unknown)."""
        found: list[frozenset[str] | None] = []
        for args, func in self.index.constructions.get(arg.cls, ()):
            if arg.index < len(args):
                found.append(self.strings(args[arg.index], func, depth + 1))
            else:
                found.append(self.strings(arg.default, ctor, depth + 1))
        return self._union(found)

    def parameter(self, ref: ParamRef, depth: int) -> frozenset[str] | None:
        """A parameter read back is worth its declared defaults (one undeclared name: unknown)."""
        self.read_parameter = True
        names = self.strings(ref.name, ref.func, depth + 1)
        if names is None:
            return None
        found: list[frozenset[str] | None] = []
        for name in sorted(names):
            defaults = self.index.parameter_defaults.get(name)
            if not defaults:
                return None
            found += [self.binding(b, depth + 1) for b in defaults]
        return self._union(found)

    def _call(self, node: Any, func: Any, depth: int) -> frozenset[str] | None:
        function = node.child_by_field_name("function")
        args = call_args(node)
        name = last_name(text(function.child_by_field_name("field") or function)) \
            if function.type == "field_expression" else last_name(text(function))
        if function.type == "field_expression" and name in PASS_THROUGH:
            return self.strings(function.child_by_field_name("argument"), func, depth + 1)
        if name in WRAPPERS and len(args) == 1:
            return self.strings(args[0], func, depth + 1)
        if name == "get_parameter" and len(args) == 1:
            return self.parameter(ParamRef(args[0], func), depth)
        if is_declare_parameter(name):
            self.read_parameter = True
            found = self.declared(args, func)
            if found is None or found[1] is None:
                return None
            return self.strings(found[1], func, depth + 1)
        return None

    def declared(self, args: list[Any], func: Any) -> tuple[str, Any] | None:
        """``(parameter name, default expression or None)`` of a ``declare*parameter*`` call's arguments.

        A leading node argument (``declare_parameter_if_not_declared(node, "p", value)``) is skipped.
        """
        if len(args) >= 2 and node_like(args[0]):
            args = args[1:]
        names = self.strings(args[0], func) if args else None
        if names is None or len(names) != 1:
            return None
        return next(iter(names)), args[1] if len(args) > 1 else None

    def literal(self, node: Any, func: Any) -> Any:
        """A parameter default as JSON: a number, a bool or one known string (``None`` otherwise)."""
        if node is None:
            return None
        if node.type == "number_literal":
            raw = text(node).rstrip("uUlLfF").replace("'", "")
            try:
                return float(raw) if any(c in raw for c in ".eE") and not raw.startswith("0x") \
                    else int(raw, 0)
            except ValueError:
                return None
        if node.type in ("true", "false"):
            return node.type == "true"
        if node.type == "call_expression" and last_name(text(node.child_by_field_name("function"))) \
                in WRAPPERS and len(call_args(node)) == 1:
            return self.literal(call_args(node)[0], func)
        strings = self.strings(node, func)
        return next(iter(strings)) if strings is not None and len(strings) == 1 else None

    @staticmethod
    def _union(parts: list[frozenset[str] | None]) -> frozenset[str] | None:
        if not parts or any(p is None for p in parts):
            return None
        out = frozenset().union(*parts)
        return out if len(out) <= MAX_CHOICES else None

    @staticmethod
    def _product(parts: list[frozenset[str] | None]) -> frozenset[str] | None:
        if not parts or any(p is None for p in parts):
            return None
        size = 1
        for part in parts:
            size *= len(part)
        if size > MAX_CHOICES:
            return None
        return frozenset("".join(combo) for combo in product(*(sorted(p) for p in parts)))


def _literal(node: Any) -> frozenset[str] | None:
    parts = []
    for child in node.named_children:
        if child.type == "string_content":
            parts.append(text(child))
        else:  # an escape sequence or a macro inside: not a plain name
            return None
    return frozenset({"".join(parts)})


def _is_this(node: Any) -> bool:
    return node is not None and node.type == "this"


def node_like(node: Any) -> bool:
    """Whether an argument is a node handle (``this``, ``node_``, ``shared_from_this()``, ``get_node_*_interface()``)."""
    if node.type == "this":
        return True
    written = text(node).lower()
    return node.type != "string_literal" and any(w in written for w in ("node", "shared_from_this", "interface"))


def call_args(call: Any) -> list[Any]:
    """The argument expressions of a call (comments left out)."""
    args = call.child_by_field_name("arguments")
    return [] if args is None else [a for a in args.named_children if a.type != "comment"]


def is_declare_parameter(name: str) -> bool:
    """``declare_parameter``, ``declare_parameter_if_not_declared``, ``declare_or_get_parameter`` …"""
    return name.startswith("declare") and "parameter" in name and not name.endswith("parameters")
