"""The shapes of rclcpp calls in tree-sitter's C++ syntax: which call creates what, on which node.

Pure functions of one call's syntax; what a name or a receiver *holds* is for
:mod:`.values` and :mod:`.extract`.
"""
from __future__ import annotations

from typing import Any

from .syntax import text
from .values import call_args, last_name, node_like

#: Base classes (last name component) that make a class a ROS node.
NODE_BASES = frozenset({"Node", "LifecycleNode"})
#: Node methods creating a named entity: method name → entity kind; the name is the first argument.
METHOD_KINDS: dict[str, str] = {
    "create_publisher": "publishers", "create_subscription": "subscriptions",
    "create_service": "services", "create_client": "clients",
    "create_action_server": "action_servers", "create_action_client": "action_clients",
    "create_generic_publisher": "publishers", "create_generic_subscription": "subscriptions",
}
#: Methods taking the message type as a string after the name (``"std_msgs/msg/String"``).
GENERIC_METHODS = frozenset({"create_generic_publisher", "create_generic_subscription"})
#: ``rclcpp_action`` free functions: the node (or its interfaces) first, then the name.
ACTION_FUNCTIONS: dict[str, str] = {"create_server": "action_servers", "create_client": "action_clients"}
COMPONENT_MACRO = "RCLCPP_COMPONENTS_REGISTER_NODE"


def is_self(node: Any) -> bool:
    """``this`` or ``*this``."""
    if node is None:
        return False
    if node.type == "pointer_expression":
        node = node.child_by_field_name("argument")
    return node is not None and node.type == "this"


def called_name(function: Any) -> str:
    if function.type == "field_expression":
        function = function.child_by_field_name("field") or function
    return last_name(text(function))


def receiver_of(function: Any) -> Any:
    return function.child_by_field_name("argument") if function.type == "field_expression" else None


def made_class(function: Any) -> str | None:
    """``X`` for ``std::make_shared<X>`` / ``X::make_shared``, ``None`` for any other callee."""
    written = text(function).replace(" ", "")
    head = written.split("<", 1)[0]
    if last_name(head) == "make_shared" and "<" in written and head.rsplit("::", 1)[-1] == "make_shared" \
            and (head == "make_shared" or head.endswith("std::make_shared")):
        return last_name(written[written.index("<") + 1:written.rindex(">")])
    if last_name(head) == "make_unique" and "<" in written:
        return last_name(written[written.index("<") + 1:written.rindex(">")])
    if written.endswith("::make_shared"):
        return last_name(written[:-len("::make_shared")])
    return None


def creates_node(function: Any) -> bool:
    return made_class(function) in NODE_BASES


def template_argument(function: Any) -> str | None:
    """The first template argument of the callee (``std_msgs::msg::String``), as written."""
    while function is not None:
        if function.type in ("template_function", "template_method"):
            arguments = function.child_by_field_name("arguments")
            first = arguments.named_children[0] if arguments is not None and arguments.named_children \
                else None
            return text(first).replace(" ", "") if first is not None else None
        function = function.child_by_field_name("field" if function.type == "field_expression" else "name")
    return None


def endpoint_form(function: Any, args: list[Any]) -> tuple[str, int, Any] | None:
    """``(kind, index of the name argument, receiver)`` when the call creates an entity."""
    name = called_name(function)
    if function.type == "field_expression":
        kind = METHOD_KINDS.get(name)
        return None if kind is None else (kind, 0, function.child_by_field_name("argument"))
    scoped = function.type == "qualified_identifier"
    scope = text(function).split("<", 1)[0].rsplit("::", 1)[0] if scoped else ""
    first_is_node = bool(args) and node_like(args[0]) and args[0].type != "string_literal"
    if name in ACTION_FUNCTIONS and ("rclcpp_action" in scope or (not scoped and first_is_node)):
        return ACTION_FUNCTIONS[name], name_index(args), args[0] if args else None
    if name in METHOD_KINDS:
        owner_scope = last_name(scope)
        if scoped and not (owner_scope in NODE_BASES or owner_scope[:1].isupper()):
            return METHOD_KINDS[name], name_index(args), args[0] if args else None
        return METHOD_KINDS[name], 0, None  # a member function's own node (``Node::create_publisher`` too)
    return None


def name_index(args: list[Any]) -> int:
    """Where the name is in a free function's arguments: after the node, or after its interfaces."""
    interfaces = 0
    for arg in args:
        if "interface" not in text(arg):
            break
        interfaces += 1
    return interfaces or 1


def qos_of(arg: Any) -> tuple[tuple[str, Any], ...] | None:
    """A QoS argument known statically: a plain depth ``10`` or ``rclcpp::QoS(10)`` (keep-last depth)."""
    if arg.type == "call_expression" and last_name(text(arg.child_by_field_name("function"))) in ("QoS", "KeepLast"):
        inner = call_args(arg)
        return qos_of(inner[0]) if len(inner) == 1 else None
    if arg.type == "number_literal" and text(arg).isdigit():
        return (("depth", int(text(arg))),)
    return None
