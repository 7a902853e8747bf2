"""The C++ files' facts joined into graph nodes and entities (``RosNode.language == "cpp"``).

Across files, because a class is declared in ``include/pkg/talker.hpp`` and
its constructor and callbacks are defined in ``src/talker.cpp``:

* a class is a node class when a base is ``Node``/``LifecycleNode`` (any
  namespace), a node class of the workspace (looked up in the same package
  first), or when ``RCLCPP_COMPONENTS_REGISTER_NODE`` registers it;
* a node class's nodes are its constructors' base initialisers; entities
  created by a member function belong to the nodes of its class and of every
  class derived from it; a node class with no known name gets one anonymous
  node (name unknown, so its relative names stay unknown);
* names are expanded per rcl (:func:`flake8_rosgraph.graph.builder.resolve_name`),
  types written as ``pkg::msg::Type`` (directly or through a ``using``/``typedef``
  alias of the file or of its package) become ``pkg/msg/Type``.

An endpoint whose name *and* type are both unknown is left out (an
informational diagnostic names it): such an end could stand in for any
endpoint of its kind, and the absence rules would have to keep quiet about the
whole workspace. With a known type it stays, as an unknown for that type only.
"""
from __future__ import annotations

import contextlib
import os
import re
from collections import defaultdict
from pathlib import Path, PurePosixPath
from typing import Any, Iterable

from ..graph import names
from ..graph.builder import _entity_order, _node_problem, _param_problem, resolve_name
from ..graph.model import Diagnostic, Entity, Location, RosNode
from .calls import NODE_BASES
from .extract import read_file
from .facts import FileFacts, NodeDecl, Owner
from .sources import CppSource, cpp_sources, included_names, mentions_rclcpp
from .syntax import load_parser

_INTERFACE = re.compile(r"^(?:::)?([A-Za-z_]\w*)::(msg|srv|action)::([A-Za-z_]\w*)$")
#: How many alias steps a type is followed through.
MAX_ALIAS_STEPS = 4
_NOUNS = {"publishers": "publisher", "subscriptions": "subscription", "services": "service server",
          "clients": "service client", "action_servers": "action server", "action_clients": "action client"}

ClassKey = tuple[str, str, str]  # (package, class name, defining source file or "" for a header)


def cpp_graph(root: Path) -> tuple[list[RosNode], list[Diagnostic]]:
    """The rclcpp nodes of the workspace under ``root`` and what reading them could not do.

    Parsed: the files that mention rclcpp, then those that include one of their headers and either
    create entities or name a node class of that header (see :func:`_through_headers`).
    """
    sources, diagnostics = cpp_sources(root)
    first = [s for s in sources if mentions_rclcpp(s)]
    if not first:
        return [], diagnostics
    parser, why_not = load_parser()
    if parser is None:
        return [], diagnostics + [Diagnostic(first[0].path, 1, why_not or "", "warning")]
    files = _read_all(first, parser, diagnostics)
    node_headers = Joiner(files).node_class_headers()
    parsed_headers = {PurePosixPath(f.path).name for f in files}
    second = [s for s in sources if not mentions_rclcpp(s) and _through_headers(s, parsed_headers, node_headers)]
    files += _read_all(second, parser, diagnostics)
    joiner = Joiner(files, root)
    nodes = joiner.nodes()
    diagnostics += [d for f in files for d in f.diagnostics] + joiner.diagnostics
    return nodes, diagnostics


#: Text that marks a file as one that may create an entity (through an included header's types).
_CREATION_MARKERS = (b"create_publisher", b"create_subscription", b"create_service", b"create_client",
                     b"create_server", b"create_action_")


def _through_headers(source: CppSource, parsed: set[str], node_headers: dict[str, set[str]]) -> bool:
    """Whether a file that does not name rclcpp still takes part: it includes a header read in the first
    round and creates entities (a plugin's ``.cpp`` whose header includes rclcpp) or names one of that
    header's node classes (``LeftDriver : public DriverBase``)."""
    included = included_names(source) & parsed
    return bool(included) and (any(m in source.data for m in _CREATION_MARKERS) or any(
        name.encode() in source.data for header in included for name in node_headers.get(header, ())))


def _read_all(sources: list[CppSource], parser: Any, diagnostics: list[Diagnostic]) -> list[FileFacts]:
    files: list[FileFacts] = []
    for source in sources:
        try:
            files.append(read_file(source, parser))
        except Exception as exc:  # one file costs only itself, whatever went wrong in it
            diagnostics.append(Diagnostic(source.path, 1, f"C++ file not read: internal error: "
                                                          f"{type(exc).__name__}: {exc}"[:200], "error"))
    return files


def interface_type(written: str | None, aliases: Iterable[dict[str, str]], scope: str = "",
                   own: frozenset[str] = frozenset()) -> str | None:
    """``std_msgs::msg::String`` (or an alias of it) → ``std_msgs/msg/String``; ``None`` otherwise.

    A relative name is looked up in the namespaces of ``scope``, innermost first, as C++ does,
    among the ``own`` interfaces of the file's package (``fleet::msg::Status`` for its
    ``msg/Status.msg``): ``msg::Status`` in namespace ``fleet`` (or ``fleet::detail``) is that
    one. Never another package's: there a ``using namespace`` may decide what ``msg`` is, and a
    wrong type is worse than an unknown one."""
    tables = list(aliases)
    enclosing = scope.split("::") if scope and own else []
    for _ in range(MAX_ALIAS_STEPS):
        if written is None:
            return None
        written = written.replace(" ", "").removeprefix("typename").removeprefix("const")
        found = next((f"{prefix}::{written}" for prefix in ("::".join(enclosing[:n])
                      for n in range(len(enclosing), 0, -1)) if f"{prefix}::{written}" in own), written)
        match = _INTERFACE.match(found)
        if match:
            return f"{match.group(1)}/{match.group(2)}/{match.group(3)}"
        written = next((table[written] for table in tables if written in table), None)
    return None


def own_interfaces(root: Path, package: str) -> frozenset[str]:
    """The interfaces the package in folder ``package`` defines, as C++ names them
    (``fleet::msg::Status`` for ``msg/Status.msg``; the folder's name is the package's)."""
    name = PurePosixPath(package).name
    out = set()
    for kind in ("msg", "srv", "action"):
        with contextlib.suppress(OSError):
            with os.scandir(root / package / kind) as entries:
                out.update(f"{name}::{kind}::{entry.name[:-len(kind) - 1]}" for entry in entries
                           if entry.name.endswith(f".{kind}") and entry.is_file())
    return frozenset(out)


class Joiner:
    """Joins the facts of all files: classes across files, nodes per owner, entities per node."""

    def __init__(self, files: list[FileFacts], root: Path | None = None) -> None:
        self.files = files
        self.root = root
        self._own: dict[str, frozenset[str]] = {}
        self.diagnostics: list[Diagnostic] = []
        self.classes: dict[ClassKey, Location] = {}
        self.bases: dict[ClassKey, tuple[str, ...]] = {}
        self.shared_by_name: dict[str, set[ClassKey]] = defaultdict(set)
        for facts in files:
            for cls in facts.classes:
                key = (cls.package, cls.name, cls.scope)
                self.classes[key] = min(self.classes.get(key, cls.location), cls.location)
                self.bases[key] = tuple(sorted(set(self.bases.get(key, ())) | set(cls.bases)))
                if not cls.scope:
                    self.shared_by_name[cls.name].add(key)
        self.components = {self.lookup(name, f.package, f.path) for f in files for name in f.components}
        self.derived: dict[ClassKey, set[ClassKey]] = defaultdict(set)
        for key, bases in self.bases.items():
            for base in bases:
                found = self.lookup(base, key[0], key[2])
                if found is not None and found != key:
                    self.derived[found].add(key)
        self.package_aliases = self._package_aliases()
        self._node_class: dict[ClassKey, bool] = {}
        self._by_owner: dict[Owner, list[RosNode]] = {}
        self._decl_nodes: dict[str, list[RosNode]] = {}
        self._class_nodes: dict[ClassKey, list[RosNode]] = defaultdict(list)
        self._node_class_of: dict[int, ClassKey] = {}

    def own_interfaces(self, package: str) -> frozenset[str]:
        """:func:`own_interfaces` of a package folder, read once (none without the root)."""
        if package not in self._own:
            self._own[package] = own_interfaces(self.root, package) if self.root is not None else frozenset()
        return self._own[package]

    def lookup(self, name: str, package: str, path: str) -> ClassKey | None:
        """The class ``name`` means in file ``path``: the file's own, its package's headers', else the one
        header class of that name in the workspace."""
        for key in ((package, name, path), (package, name, "")):
            if key in self.classes:
                return key
        found = self.shared_by_name.get(name, set())
        return next(iter(found)) if len(found) == 1 else None

    def is_node_class(self, key: ClassKey) -> bool:
        if key not in self._node_class:
            self._node_class[key] = False  # a cycle in the bases is no node
            self._node_class[key] = key in self.components or any(
                base in NODE_BASES or self._is_node_base(base, key[0], key[2]) for base in self.bases.get(key, ()))
        return self._node_class[key]

    def _is_node_base(self, base: str, package: str, path: str) -> bool:
        found = self.lookup(base, package, path)
        return found is not None and self.is_node_class(found)

    def node_class_headers(self) -> dict[str, set[str]]:
        """Header file name → the node classes it defines."""
        out: dict[str, set[str]] = defaultdict(set)
        for key, location in self.classes.items():
            if not key[2] and self.is_node_class(key):
                out[PurePosixPath(location.path).name].add(key[1])
        return out

    def descendants(self, key: ClassKey) -> list[ClassKey]:
        out: list[ClassKey] = []
        stack = [key]
        while stack:
            current = stack.pop()
            if current in out:
                continue
            out.append(current)
            stack.extend(sorted(self.derived.get(current, ())))
        return out

    def _package_aliases(self) -> dict[str, dict[str, str]]:
        """Per package, the aliases that mean one thing across its files."""
        seen: dict[str, dict[str, set[str]]] = defaultdict(lambda: defaultdict(set))
        for facts in self.files:
            for name, target in facts.aliases.items():
                seen[facts.package][name].add(target.replace(" ", ""))
        return {package: {name: next(iter(t)) for name, t in table.items() if len(t) == 1}
                for package, table in seen.items()}

    # -- nodes -----------------------------------------------------------------------------------
    def nodes(self) -> list[RosNode]:
        for facts in self.files:
            for decl in facts.decls:
                self._add_decl(decl)
        entities: dict[int, dict[tuple, Entity]] = defaultdict(dict)
        for facts in self.files:
            aliases = (facts.aliases, self.package_aliases.get(facts.package, {}))
            for endpoint in facts.endpoints:
                type_ = interface_type(endpoint.type_written, aliases, endpoint.scope,
                                       self.own_interfaces(facts.package) if endpoint.scope else frozenset())
                kept = False
                for node in self.owner_nodes(endpoint.owner, endpoint.location):
                    for raw in endpoint.names:
                        name, problem = resolve_name(raw, node)
                        if name is None and type_ is None:
                            continue
                        kept = True
                        entity = Entity(endpoint.kind, name, endpoint.location, raw_name=raw, type=type_,
                                        qos=dict(endpoint.qos) if endpoint.qos else None, invalid=problem,
                                        name_suffix=names.known_suffix(raw) if name is None else None)
                        entities[id(node)].setdefault(_entity_order(entity), entity)
                if not kept:
                    self.diagnostics.append(Diagnostic(
                        endpoint.location.path, endpoint.location.line,
                        f"C++ {_NOUNS[endpoint.kind]} with unknown name and type ({endpoint.written}): "
                        "not used as a partner end", "info"))
            for param in facts.parameters:
                for node in self.owner_nodes(param.owner, param.location):
                    entity = Entity("parameters", param.name, param.location, raw_name=param.name,
                                    default=param.default, invalid=_param_problem(param.name))
                    entities[id(node)].setdefault(_entity_order(entity), entity)
        out: dict[int, RosNode] = {}
        for group in (*self._decl_nodes.values(), *self._by_owner.values()):
            for node in group:
                out[id(node)] = node
        anonymous = {id(n) for group in self._by_owner.values() for n in group} - \
            {id(n) for group in self._decl_nodes.values() for n in group}
        for node in out.values():
            bucket = entities.get(id(node), {})
            node.entities = [bucket[k] for k in sorted(bucket)]
        # An anonymous node exists only for its entities; a node creation is a node even without any.
        kept = [n for n in out.values() if (n.entities or id(n) not in anonymous) and not self._abstract(n)]
        return sorted(kept, key=lambda n: (n.fqn or "", n.location, n.cls or ""))

    def _abstract(self, node: RosNode) -> bool:
        """A base class's own node whose name its constructor takes from a parameter, when classes
        derived from it make the named nodes (``DriverBase(name) : Node(name)``)."""
        key = self._node_class_of.get(id(node))
        return node.name is None and key is not None and any(
            self._class_nodes.get(sub) for sub in self.descendants(key) if sub != key)

    def _add_decl(self, decl: NodeDecl) -> None:
        cls_key = None
        if decl.cls is not None:
            path = decl.location.path
            cls_key = self.lookup(decl.cls, decl.package, path) or (decl.package, decl.cls, path)
            if decl.base not in NODE_BASES and not self._is_node_base(decl.base or "", decl.package, path):
                return  # a base initialiser of a class that is no node
        made = [RosNode(name, None if ns is None else names.normalize_namespace(ns), decl.location,
                        decl.cls, invalid=_node_problem(name, None if ns is None else names.normalize_namespace(ns)),
                        language="cpp")
                for name in decl.names for ns in decl.namespaces]
        self._decl_nodes[decl.key] = made
        if cls_key is not None:
            self._class_nodes[cls_key].extend(made)
            self._node_class_of.update((id(node), cls_key) for node in made)

    def owner_nodes(self, owner: Owner, where: Location) -> list[RosNode]:
        """The nodes an entity of ``owner`` is created on (an anonymous one when none is known)."""
        if owner in self._by_owner:
            return self._by_owner[owner]
        found: list[RosNode] = []
        location = where
        cls = owner.name if owner.kind == "class" else None
        if owner.kind == "decl":
            found = self._decl_nodes.get(owner.name, [])
        elif owner.kind == "class":
            key = self.lookup(owner.name, owner.package, owner.path) or (owner.package, owner.name, owner.path)
            for sub in self.descendants(key):
                found += [n for n in self._class_nodes.get(sub, ())
                          if all(n is not f for f in found) and not self._abstract(n)]
            location = self.classes.get(key, where)
        if not found:
            found = [RosNode(None, None, location, cls, language="cpp")]
        self._by_owner[owner] = found
        return found
