"""What one C++ file says about the ROS graph: node classes, node creations, rclcpp calls.

Read in two passes over the tree-sitter tree. The first walk records the
bindings :mod:`.values` needs (locals, members, constants, ``#define``s,
parameter reads), the classes with their bases, type aliases and every call;
the second evaluates the calls once all bindings are known:

* ``create_publisher<T>("name", qos)``, ``create_subscription<T>("name", qos, cb)``,
  ``create_service<T>("name", cb)``, ``create_client<T>("name")`` and the
  action forms ``create_action_server/client`` on a receiver (``this->``,
  ``node->``, ``node_->``, ``node.``) or none (a member function's own node);
  the free functions ``rclcpp::create_publisher<T>(node, "name", …)`` and
  ``rclcpp_action::create_server/create_client<T>(node, "name", …)`` (also with
  the node interfaces spelled out before the name);
* nodes: a constructor initialiser of a base class (``: Node("talker", options)``,
  ``rclcpp::Node("talker", "ns")``, ``LifecycleNode(...)``, a workspace node class),
  ``std::make_shared<rclcpp::Node>("name")``, ``rclcpp::Node::make_shared("name")``,
  ``rclcpp::Node node("name")``; ``RCLCPP_COMPONENTS_REGISTER_NODE(Cls)`` marks a
  node class;
* parameters: every ``declare*parameter*`` call whose name is known.

A call whose receiver is not one of these nodes (a plugin's ``parent.lock()``)
belongs to an anonymous node of its class: its relative names stay unknown.
Calls inside a region tree-sitter could not parse are skipped.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ..graph.model import Diagnostic
from .calls import (ACTION_FUNCTIONS, COMPONENT_MACRO, GENERIC_METHODS, METHOD_KINDS, NODE_BASES, called_name,
                    creates_node, endpoint_form, is_self, made_class, qos_of, receiver_of, template_argument)
from .facts import ClassFact, EndpointFact, FileFacts, NodeDecl, Owner, ParameterFact
from .sources import CppSource
from .syntax import MAX_SYNTAX_NODES, BudgetExceeded, SourceText, damage_diagnostic, nodes_of_types, text
from .values import (UNKNOWN, Binding, CtorArg, Evaluator, FileIndex, ParamRef, call_args, is_declare_parameter,
                     is_syntax, last_name, node_like)

_SCOPES = ("class_specifier", "struct_specifier")
#: Syntax that may hold a binding or a call but none worth reading (a default argument, a
#: template argument): passed over with all it holds.
_OPAQUE = ("template_argument_list", "parameter_list", "type_descriptor", "qualified_identifier")
#: The syntax the first pass reads: bindings and calls, the scopes they are in, and the opaque syntax.
_WALKED = ("declaration", "field_declaration", "assignment_expression", "call_expression", "preproc_def",
           "alias_declaration", "type_definition", "using_declaration", "class_specifier", "struct_specifier",
           "function_definition", "lambda_expression", *_OPAQUE)
#: Calls read in the second pass: those that may create an entity, a node or a parameter.
_INTERESTING_CALLS = frozenset(METHOD_KINDS) | frozenset(ACTION_FUNCTIONS) | {"make_shared", "make_unique"}
#: Values that hold no node (``node_ = nullptr;`` at shutdown does not make another owner).
_NULLS = frozenset({"nullptr", "null"})
#: Calls that bind a value or mark a class in the first pass.
_BINDING_CALLS = frozenset({COMPONENT_MACRO, "get_parameter", "get_parameter_or"})
_DECLARATORS = ("pointer_declarator", "reference_declarator", "array_declarator", "init_declarator",
                "function_declarator", "parenthesized_declarator")


@dataclass(frozen=True)
class _Site:
    """A call seen in the first walk, with its enclosing function and class."""

    call: Any
    func: Any
    cls: str | None


def read_file(source: CppSource, parser: Any) -> FileFacts:
    """The facts of one C++ file; never raises on bad input (damage and limits become diagnostics)."""
    facts = FileFacts(source.path, source.package)
    tree = parser.parse(source.data)
    src = SourceText(source.path, source.data)
    damage = damage_diagnostic(src, tree.root_node)
    if damage is not None:
        facts.diagnostics.append(damage)
    reader = _Reader(src, facts)
    try:
        reader.first_pass(tree.root_node, parser.language)
    except BudgetExceeded:
        facts.diagnostics.append(Diagnostic(source.path, 1, f"C++ file read in part: more than "
                                                            f"{MAX_SYNTAX_NODES} syntax nodes", "warning"))
    reader.index.settle()
    reader.second_pass()
    return facts


class _Reader:
    def __init__(self, src: SourceText, facts: FileFacts) -> None:
        self.src = src
        self.facts = facts
        self.index = FileIndex()
        self.values = Evaluator(self.index)
        self.sites: list[_Site] = []
        self.inits: list[tuple[str, Any, Any]] = []  # (class, field_initializer, constructor)
        self.node_values: list[tuple[Any, Any]] = []  # (rclcpp::Node node("x") declarator, func)

    # -- first pass: bindings, classes, calls ----------------------------------------------------
    def first_pass(self, root: Any, language: Any) -> None:
        """Hand each syntax node of :data:`_WALKED` types to its reader, with the function and class
        it is in, in source order; nothing inside :data:`_OPAQUE` syntax. tree-sitter finds the nodes
        (:func:`.syntax.nodes_of_types`): a fifth of all nodes, and handing every node to Python made
        this pass a third slower."""
        handlers = {
            "declaration": self._declaration, "field_declaration": self._field,
            "assignment_expression": self._assignment, "call_expression": self._call,
            "preproc_def": self._macro, "alias_declaration": self._alias, "type_definition": self._alias,
            "using_declaration": self._alias,
        }
        scopes: list[tuple[int, Any, str | None]] = []  # (end byte, function, class) of enclosing scopes
        skipped_until = -1  # the end byte of the opaque syntax being passed over
        for seen, node in enumerate(nodes_of_types(language, root, _WALKED), 1):
            if seen > MAX_SYNTAX_NODES:
                raise BudgetExceeded
            start = node.start_byte
            if start < skipped_until:
                continue
            while scopes and scopes[-1][0] <= start:
                scopes.pop()
            func, cls = scopes[-1][1:] if scopes else (None, None)
            kind = node.type
            handler = handlers.get(kind)
            if handler is not None:
                handler(node, func, cls)
            elif kind in _SCOPES:
                scopes.append((node.end_byte, func, self._class(node) or cls))
            elif kind == "function_definition":
                cls = _method_class(node) or cls
                self._function(node, cls)
                scopes.append((node.end_byte, node, cls))
            elif kind == "lambda_expression":
                if func is not None:
                    self._parameters(node.child_by_field_name("declarator"), func)
            else:
                skipped_until = node.end_byte  # opaque

    def _class(self, node: Any) -> str | None:
        name = node.child_by_field_name("name")
        if name is None or node.child_by_field_name("body") is None:
            return None
        clause = next((c for c in node.named_children if c.type == "base_class_clause"), None)
        bases = () if clause is None else tuple(
            last_name(text(c)) for c in clause.named_children if c.type != "access_specifier")
        cls = last_name(text(name))
        self.facts.classes.append(ClassFact(self.facts.package, cls, bases, self.src.location(node)))
        return cls

    def _function(self, node: Any, cls: str | None) -> None:
        declarator = _function_declarator(node)
        if declarator is None:
            return
        name = declarator.child_by_field_name("declarator")
        constructor = cls is not None and name is not None and last_name(text(name)) == cls
        self._parameters(declarator, node, cls if constructor else None)
        if not constructor:
            return
        for child in node.named_children:
            if child.type == "field_initializer_list":
                for init in child.named_children:
                    if init.type == "field_initializer":
                        self._initializer(init, node, cls)

    def _initializer(self, init: Any, ctor: Any, cls: str) -> None:
        target = init.named_children[0] if init.named_children else None
        args = next((c for c in init.named_children if c.type in ("argument_list", "initializer_list")), None)
        if target is None or args is None:
            return
        if target.type == "field_identifier":
            self.index.members.setdefault(text(target), []).append(Binding(args, ctor))
        self.inits.append((cls, init, ctor))

    def _parameters(self, declarator: Any, func: Any, constructed: str | None = None) -> None:
        """Parameters are unknown, except a constructor's: the arguments the file constructs it with."""
        params = declarator.child_by_field_name("parameters") if declarator is not None else None
        for index, param in enumerate(params.named_children if params is not None else ()):
            name = _declared_name(param.child_by_field_name("declarator"))
            if name is not None:
                value = CtorArg(constructed, index, param.child_by_field_name("default_value")) \
                    if constructed else UNKNOWN
                self.index.declare_local(func, name, Binding(value, func))

    def _declaration(self, node: Any, func: Any, cls: str | None = None) -> None:
        node_type = node.child_by_field_name("type")
        by_value = node_type is not None and last_name(text(node_type)) in NODE_BASES
        for declarator in node.children_by_field_name("declarator"):
            name = _declared_name(declarator)
            if name is None or declarator.type == "function_declarator":
                continue
            value = declarator.child_by_field_name("value") if declarator.type == "init_declarator" else None
            binding = Binding(value, func) if value is not None else None
            if by_value and value is not None and value.type in ("argument_list", "initializer_list"):
                self.node_values.append((declarator, func))
            if func is not None:
                self.index.declare_local(func, name, binding)
            elif binding is not None:
                self.index.constants.setdefault(name, []).append(binding)

    def _field(self, node: Any, func: Any = None, cls: str | None = None) -> None:
        default = node.child_by_field_name("default_value")
        for declarator in node.children_by_field_name("declarator"):
            name = _declared_name(declarator)
            if name is not None and default is not None:
                self.index.members.setdefault(name, []).append(Binding(default))

    def _assignment(self, node: Any, func: Any, cls: str | None = None) -> None:
        left, right = node.child_by_field_name("left"), node.child_by_field_name("right")
        operator = node.child_by_field_name("operator")
        binding = Binding(right, func) if operator is not None and text(operator) == "=" else Binding(UNKNOWN)
        if left is not None:
            self._bind(left, func, binding)

    def _bind(self, target: Any, func: Any, binding: Binding) -> None:
        """Record a value given to ``x`` (local or member, sorted out later) or ``this->x`` (a member)."""
        if target.type == "identifier":
            self.index.assign(func, text(target), binding)
        elif target.type == "field_expression" and is_self(target.child_by_field_name("argument")):
            self.index.members.setdefault(text(target.child_by_field_name("field")), []).append(binding)

    def _call(self, node: Any, func: Any, cls: str | None) -> None:
        function = node.child_by_field_name("function")
        if function is None:
            return
        name = called_name(function)
        if name not in _BINDING_CALLS and name not in _INTERESTING_CALLS and not is_declare_parameter(name):
            return
        args = call_args(node)
        if name == COMPONENT_MACRO and len(args) == 1:
            self.facts.components.append(last_name(text(args[0])))
        elif name in ("get_parameter", "get_parameter_or") and len(args) >= 2:
            out = args[1]
            ref = Binding(ParamRef(args[0], func), func)
            bindings = [ref, Binding(args[2], func)] if name == "get_parameter_or" and len(args) > 2 else [ref]
            for binding in bindings:
                self._bind(out, func, binding)
        made = made_class(function) if name in ("make_shared", "make_unique") else None
        if made is not None and made not in NODE_BASES:
            self.index.constructions.setdefault(made, []).append((args, func))
        if not node.has_error and (name in _INTERESTING_CALLS or is_declare_parameter(name)):
            self.sites.append(_Site(node, func, cls))

    def _macro(self, node: Any, func: Any = None, cls: str | None = None) -> None:
        name, value = node.child_by_field_name("name"), node.child_by_field_name("value")
        written = text(value).strip() if value is not None else ""
        if name is not None and len(written) >= 2 and written[0] == written[-1] == '"' \
                and '"' not in written[1:-1] and "\\" not in written:
            self.index.macros.setdefault(text(name), []).append(written[1:-1])

    def _alias(self, node: Any, func: Any = None, cls: str | None = None) -> None:
        if node.type == "alias_declaration":
            name, target = node.child_by_field_name("name"), node.child_by_field_name("type")
            if name is not None and target is not None:
                self.facts.aliases[text(name)] = text(target)
        elif node.type == "type_definition":
            target = node.child_by_field_name("type")
            for declarator in node.children_by_field_name("declarator"):
                if target is not None and declarator.type == "type_identifier":
                    self.facts.aliases[text(declarator)] = text(target)
        else:
            named = [c for c in node.named_children if c.type == "qualified_identifier"]
            if named and not any(c.type == "namespace" for c in node.children):
                self.facts.aliases[last_name(text(named[0]))] = text(named[0])

    # -- second pass: parameters, nodes, endpoints -----------------------------------------------
    def second_pass(self) -> None:
        for site in self.sites:
            self._declared_parameter(site)
        for cls, init, ctor in self.inits:
            self._base_initializer(cls, init, ctor)
        for site in self.sites:
            self._node_creation(site)
        for declarator, func in self.node_values:
            args = call_args_of(declarator.child_by_field_name("value"))
            self._decl(declarator, args, func, None, "Node")
        for site in self.sites:
            self._endpoint(site)

    def _declared_parameter(self, site: _Site) -> None:
        function = site.call.child_by_field_name("function")
        name = called_name(function)
        if not is_declare_parameter(name):
            return
        args = call_args(site.call)
        found = self.values.declared(args, site.func)
        if found is None:
            return
        param, default = found
        self.index.parameter_defaults.setdefault(param, []).append(
            Binding(default if default is not None else UNKNOWN, site.func))
        receiver = receiver_of(function)
        if function.type != "field_expression" and len(args) >= 2 and node_like(args[0]):
            receiver = args[0]
        owner = self.owner(receiver, site.func, site.cls)
        self.facts.parameters.append(ParameterFact(param, self.values.literal(default, site.func),
                                                   self.src.location(site.call), owner))

    def _base_initializer(self, cls: str, init: Any, ctor: Any) -> None:
        base = last_name(text(init.named_children[0]))
        args_node = next(c for c in init.named_children if c.type in ("argument_list", "initializer_list"))
        args = [a for a in args_node.named_children if a.type != "comment"]
        if base[:1].isupper() and args:  # a base class, not a member (``count_(0)``)
            self._decl(init, args, ctor, cls, base)

    def _node_creation(self, site: _Site) -> None:
        function = site.call.child_by_field_name("function")
        if creates_node(function):
            self._decl(site.call, call_args(site.call), site.func, None, "Node")

    def _decl(self, node: Any, args: list[Any], func: Any, cls: str | None, base: str) -> None:
        names = self._choices(args[0], func) if args else (None,)
        namespaces: tuple[str | None, ...] = ("",)  # Node(name) and Node(name, options): the root
        if len(args) >= 3 or (len(args) == 2 and self.values.strings(args[1], func) is not None):
            namespaces = self._choices(args[1], func)  # Node(name, namespace[, options])
        self.facts.decls.append(NodeDecl(self._key(node), names, namespaces, self.src.location(node),
                                         self.facts.package, cls, base))

    def _endpoint(self, site: _Site) -> None:
        call = site.call
        function = call.child_by_field_name("function")
        form = endpoint_form(function, call_args(call))
        if form is None:
            return
        kind, name_index, receiver = form
        args = call_args(call)
        if name_index >= len(args):
            return
        message_type = template_argument(function)
        qos_at = name_index + 1
        if called_name(function) in GENERIC_METHODS:  # (name, "pkg/msg/Type", qos, ...)
            qos_at += 1
            types = self.values.strings(args[name_index + 1], site.func) if qos_at - 1 < len(args) else None
            message_type = next(iter(types)).replace("/", "::") if types and len(types) == 1 else None
        qos = qos_of(args[qos_at]) if kind in ("publishers", "subscriptions") and qos_at < len(args) else None
        written = text(call).split("\n", 1)[0][:80]
        self.values.read_parameter = False
        names = self._choices(args[name_index], site.func)
        if self.values.read_parameter and None not in names:
            # The default of a parameter: a parameter file or launch file may set another name,
            # and the C++ nodes are not bound to launch files, so the name may also be another one.
            names += (None,)
        self.facts.endpoints.append(EndpointFact(
            kind, names, message_type, qos,
            self.src.location(call), self.owner(receiver, site.func, site.cls), written, _scope(call)))

    # -- helpers ---------------------------------------------------------------------------------
    def _choices(self, node: Any, func: Any) -> tuple[str | None, ...]:
        found = self.values.strings(node, func)
        return tuple(sorted(found)) if found else (None,)

    def _key(self, node: Any) -> str:
        return f"{self.src.path}:{node.start_byte}"

    def owner(self, receiver: Any, func: Any, cls: str | None) -> Owner:
        """The node an entity created through ``receiver`` (``None``: the member function's own) is on."""
        found = self._owner(receiver, func, cls, 0)
        if found is not None:
            return found
        scope = cls or (_function_name(func) if func is not None else "") or self.src.path
        return Owner("anonymous", self.facts.package, scope, self.src.path)

    def _owner(self, receiver: Any, func: Any, cls: str | None, depth: int) -> Owner | None:
        if depth > 6:
            return None
        if receiver is None or is_self(receiver):
            return Owner("class", self.facts.package, cls, self.src.path) if cls else None
        if receiver.type == "call_expression":
            function = receiver.child_by_field_name("function")
            name = called_name(function)
            if name.endswith("_interface") or name in ("get", "shared_from_this"):
                return self._owner(receiver_of(function), func, cls, depth + 1)
            if creates_node(function):
                return Owner("decl", self.facts.package, self._key(receiver), self.src.path)
            return None
        if receiver.type == "identifier":
            bindings = self.index.bindings(text(receiver), func)
        elif receiver.type == "field_expression" and is_self(receiver.child_by_field_name("argument")):
            bindings = self.index.bindings(text(receiver.child_by_field_name("field")), func, member_only=True)
        else:
            return None
        owners = {self._owner_of_binding(b, cls, depth) for b in bindings or ()
                  if not is_syntax(b.value) or b.value.type not in _NULLS}
        return owners.pop() if len(owners) == 1 else None

    def _owner_of_binding(self, binding: Binding, cls: str | None, depth: int) -> Owner | None:
        value = binding.value
        if not is_syntax(value):
            return None
        parent = value.parent
        if value.type in ("argument_list", "initializer_list") and parent is not None:
            if any(parent is d or self._key(parent) == self._key(d) for d, _ in self.node_values):
                return Owner("decl", self.facts.package, self._key(parent), self.src.path)
            inner = [a for a in value.named_children if a.type != "comment"]
            return self._owner(inner[0], binding.func, cls, depth + 1) if len(inner) == 1 else None
        if value.type == "call_expression":
            function = value.child_by_field_name("function")
            made = made_class(function)
            if made is not None and made not in NODE_BASES:
                return Owner("class", self.facts.package, made, self.src.path)
        return self._owner(value, binding.func, cls, depth + 1)


def call_args_of(args_node: Any) -> list[Any]:
    return [a for a in args_node.named_children if a.type != "comment"] if args_node is not None else []


def _declared_name(declarator: Any) -> str | None:
    while declarator is not None and declarator.type in _DECLARATORS:
        inner = declarator.child_by_field_name("declarator")
        if inner is None:  # reference_declarator keeps its name as a plain child
            inner = next((c for c in declarator.named_children if c.type.endswith("identifier")
                          or c.type in _DECLARATORS), None)
        declarator = inner
    if declarator is None or declarator.type not in ("identifier", "field_identifier"):
        return None
    return text(declarator)


def _function_declarator(node: Any) -> Any:
    declarator = node.child_by_field_name("declarator")
    while declarator is not None and declarator.type != "function_declarator":
        declarator = declarator.child_by_field_name("declarator") \
            if declarator.type in _DECLARATORS else None
    return declarator


def _function_name(func: Any) -> str:
    declarator = _function_declarator(func)
    name = declarator.child_by_field_name("declarator") if declarator is not None else None
    return text(name) if name is not None else ""


def _scope(node: Any) -> str:
    """The scope C++ looks names up in at ``node`` (:attr:`.facts.EndpointFact.scope`): the named
    namespaces around it, then the qualifier of the function it is in when that function is
    defined outside its class or namespace (``void fleet::Bridge::start()``)."""
    parts: list[str] = []
    qualifier = ""
    parent = node.parent
    while parent is not None:
        if parent.type == "namespace_definition":
            name = parent.child_by_field_name("name")
            if name is not None:
                parts.append(text(name).replace(" ", ""))
        elif parent.type == "function_definition" and not qualifier and not parts:
            declarator = _function_declarator(parent)
            name = declarator.child_by_field_name("declarator") if declarator is not None else None
            if name is not None and name.type == "qualified_identifier":
                qualifier = text(name).replace(" ", "").rsplit("::", 1)[0]
        parent = parent.parent
    return "::".join([*reversed(parts), *([qualifier] if qualifier else [])])


def _method_class(func: Any) -> str | None:
    """``Talker`` for ``void Talker::on_timer()`` (and ``ns::Talker<T>::…``); ``None`` otherwise."""
    declarator = _function_declarator(func)
    name = declarator.child_by_field_name("declarator") if declarator is not None else None
    if name is None or name.type != "qualified_identifier":
        return None
    scope = text(name).rsplit("::", 1)[0]
    return last_name(scope) or None
