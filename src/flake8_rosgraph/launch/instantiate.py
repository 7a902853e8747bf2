"""rcl semantics: a launched node made from its code-level node.

What ``--ros-args`` from launch do when the node starts (rcl ``node.c``,
``remap.c``, ``arguments.c``):

* ``__node:=`` (the launch ``name``) replaces the node name and ``__ns:=``
  (the launch namespace, pushed namespaces included) the namespace, for
  every node the executable creates — but for what a node's own ``cli_args``
  set: rcl reads a node's local arguments first;
* every topic/service/action name is expanded with the *new* name and
  namespace, then the remap rules are tried in order — the scope's
  ``SetRemap`` rules, then the node's own — on the fully expanded name, and
  the first match wins; its replacement is expanded in the node's context;
* parameters reach the node from ``SetParameter`` in scope, the node's inline
  parameters and every parameter-file section whose node pattern
  (``/**``, ``*``, ``/ns/name``) matches the node's fully qualified name.
"""
from __future__ import annotations

from dataclasses import replace
from pathlib import Path
from typing import Any

from ..graph import names
from ..graph.model import NAMED_KINDS, Diagnostic, Entity, Location, RosGraph, RosNode
from .model import ExecutableRef, Instance, LaunchedNode, System
from .param_files import Section, YamlError, read_param_file


def _node_name(launched: LaunchedNode, code: RosNode) -> str | None:
    if "name" in code.local_overrides:
        return code.name
    if launched.is_unresolved("name"):
        return None
    return launched.name if launched.name is not None else code.name


def _namespace(launched: LaunchedNode, code: RosNode) -> str | None:
    if "namespace" in code.local_overrides:
        return code.namespace
    if launched.is_unresolved("namespace"):
        return None
    return launched.namespace if launched.namespace is not None else code.namespace


#: Stands for a node whose name is unknown where the result does not depend on it.
_ANY_NODE = "unknown"


def _needs_node_name(raw: str, rules: list[names.RemapRule]) -> bool:
    """Whether expanding and remapping ``raw`` needs the node's name: a private name, a
    ``{node}`` substitution, or a rule for one node or with a private side."""
    def private(text: str) -> bool:
        return text.startswith("~") or "{node}" in text
    return private(raw) or any(rule.node is not None or private(rule.match) or private(rule.replacement)
                               for rule in rules)


def _launched_suffix(entity: Entity, resolved: str | None, rules: list[names.RemapRule],
                     launched: LaunchedNode) -> str | None:
    """The known end of a launched entity's unknown name (:attr:`Entity.name_suffix`): none
    when a launch remap may apply (remaps match the expanded name, unknown here), nor when
    the code's own remaps changed it (its code-level name does not end so)."""
    if resolved is not None or rules or launched.is_unresolved("remap"):
        return None
    suffix = names.known_suffix(entity.raw_name)
    if suffix is None or (entity.name is None and entity.name_suffix != suffix) or (
            entity.name is not None and not entity.name.endswith(suffix)):
        return None
    return suffix


def launch_info(launched: LaunchedNode) -> dict[str, Any]:
    """The ``"launch"`` object of a node in the graph JSON."""
    return {"file": launched.launch_file, "line": launched.location.line,
            "executable": launched.executable, "package": launched.package}


class Instantiator:
    def __init__(self, root: Path) -> None:
        self.root = Path(root)
        self._files: dict[str, list[Section] | str] = {}
        #: The graph the indexes below are of (every system of a workspace binds to the same one).
        self._graph: RosGraph | None = None
        self._by_location: dict[Location, list[RosNode]] = {}
        self._named_cpp: list[RosNode] = []

    def _index(self, graph: RosGraph) -> None:
        """Index ``graph``'s nodes once for all of its systems, not once per launch file."""
        if self._graph is graph:
            return
        self._graph = graph
        self._by_location = {}
        for node in graph.nodes:
            self._by_location.setdefault(node.location, []).append(node)
        # A C++ node of unknown name stands for the owner of entities made through a pointer
        # (``node->create_client``), not for a node of its own: it stays as written.
        self._named_cpp = [node for node in graph.nodes if node.language == "cpp" and node.name is not None]

    def sections(self, path: str) -> list[Section] | str:
        """A parameter file's sections, or why it cannot be read."""
        if path not in self._files:
            try:
                self._files[path] = read_param_file(self.root, path)
            except (OSError, UnicodeDecodeError) as exc:
                self._files[path] = f"cannot read: {exc}"
            except YamlError as exc:
                self._files[path] = f"not read: {exc}"
        return self._files[path]

    def system(self, graph: RosGraph, system: System) -> None:
        """Bind every launched node of ``system`` whose code is known; fills ``system.instances``."""
        self._index(graph)
        reported: set[tuple[str, int, str]] = set()
        for launched in system.nodes:
            for file in launched.param_files:
                problem = f"parameter file '{file.written}' is not a file in the workspace" \
                    if file.path is None else self.sections(file.path)
                if file.path is not None and not isinstance(problem, str):
                    system.parameter_files[file.path] = problem
                if isinstance(problem, str):
                    key = (file.location.path, file.location.line, problem)
                    if key not in reported:
                        reported.add(key)
                        system.problems.append(Diagnostic(file.location.path, file.location.line, problem))
            if launched.target.status == "no-python":
                system.instances.extend(self.instance(launched, code, analysed=False)
                                        for code in self.cpp_nodes(graph, launched.target))
                continue
            if launched.target.status != "found":
                continue
            classes = set(launched.target.node_classes)
            for site in launched.target.node_sites:
                for code in self._by_location.get(site, ()):
                    if (site, code.cls) in classes:
                        system.instances.append(self.instance(launched, code))
        system.problems.extend(sorted({problem for instance in system.instances
                                       for problem in _unread_names(instance.node)}))

    def cpp_nodes(self, graph: RosGraph, target: ExecutableRef) -> list[RosNode]:
        """The rclcpp nodes a C++ executable runs: those created in its source files (as CMake
        lists them) and those of the class it registers as its component (``PLUGIN
        "pkg::Driver"``); when those create none (its ``main`` only names a class of a
        library it links), the nodes of the linked libraries' sources if they are of one class.
        No tie is guessed from words in the sources (``Joy`` in ``sensor_msgs::msg::Joy``)."""
        if not target.cpp_sources and not target.cpp_plugins and not target.cpp_linked:
            return []
        self._index(graph)
        named = self._named_cpp
        sources = set(target.cpp_sources)
        plugins = {plugin.rsplit("::", 1)[-1] for plugin in target.cpp_plugins}
        found = [node for node in named if node.location.path in sources
                 or (node.cls is not None and node.cls.rsplit("::", 1)[-1] in plugins)]
        if found:
            return found
        linked_sources = set(target.cpp_linked)
        linked = [node for node in named if node.location.path in linked_sources]
        return linked if len({node.cls for node in linked}) == 1 else []

    def instance(self, launched: LaunchedNode, code: RosNode, analysed: bool = True) -> Instance:
        """``analysed``: false for a C++ node, whose names and parameters the analysis reads
        only in part (literal names, no generated code): its launch name, namespace and remaps
        apply, but nothing is judged "unused" on it."""
        name, namespace = _node_name(launched, code), _namespace(launched, code)
        rules = [names.RemapRule(r.source, r.target) for r in launched.remaps]
        fqn = None if name is None or namespace is None else names.fqn(name, namespace)
        settings = self.settings(launched, fqn)
        values = _set_values(settings)
        unread = next((file.location for file in launched.param_files
                       if file.path is None or isinstance(self.sections(file.path), str)), None)
        hits: set[int] = set()
        expanded: set[str] = set()
        entities: list[Entity] = []
        known = True
        foreign = set(launched.target.foreign_end_sites)
        own = [entity for entity in code.entities if entity.location not in foreign]
        for entity in _named_by_parameters(own, values, unread):
            if entity.kind not in NAMED_KINDS:
                entities.append(entity)
                continue
            raw = names.rebuild_in_namespace(entity.raw_name, code.namespace, namespace)
            if raw != entity.raw_name:  # built from the namespace, which the launch file sets
                entity = replace(entity, raw_name=raw, name=None, invalid=None)
            resolved, problem, hit = self.resolve(entity, name, namespace, rules)
            if hit is not None:
                hits.add(hit)
            if resolved is not None and name is not None and namespace is not None \
                    and entity.raw_name is not None:
                before, _ = names.expand_topic_name(entity.raw_name, name, namespace)
                expanded.add(before or resolved)
            known = known and resolved is not None
            suffix = _launched_suffix(entity, resolved, rules, launched)
            entities.append(replace(entity, name=resolved, invalid=problem or entity.invalid,
                                    name_suffix=suffix))
        node = RosNode(name, namespace, code.location, code.cls,
                       conditional=code.conditional or launched.conditional, cls_path=code.cls_path,
                       invalid=code.invalid, entities=entities, language=code.language)
        node.launch = launch_info(launched)
        return Instance(launched, node, code, frozenset(hits), settings,
                        known and analysed, tuple(sorted(expanded)), analysed=analysed)

    @staticmethod
    def resolve(entity: Entity, name: str | None, namespace: str | None,
                rules: list[names.RemapRule]) -> tuple[str | None, str | None, int | None]:
        """The entity's name after expansion and remapping, its problem, and the rule that matched."""
        raw = entity.raw_name
        if raw is None:
            return None, None, None
        if name is None and not _needs_node_name(raw, rules):
            name = _ANY_NODE  # a relative name and these rules depend on the namespace only
        if name is None or namespace is None or not names.validate_node_name(name).ok \
                or not names.validate_namespace(namespace).ok:
            # An unknown or invalid launch name/namespace (ROS203 reports the latter at the
            # launch file) leaves absolute names as written and the rest unknown.
            return (raw, None, None) if raw.startswith("/") else (None, None, None)
        expanded, check = names.expand_topic_name(raw, name, namespace)
        if expanded is None:
            return entity.name, check.reason, None
        rule = names.first_remap_match(expanded, rules, name, namespace)
        if rule is None:
            return expanded, None if check.ok else check.reason, None
        remapped, check = names.expand_topic_name(rule.replacement, name, namespace)
        if remapped is None:
            return rule.replacement, check.reason, rules.index(rule)
        return remapped, None if check.ok else check.reason, rules.index(rule)

    def settings(self, launched: LaunchedNode, fqn: str | None) -> list[tuple[str, Any, Location, str]]:
        """The parameters that reach the launched node of full name ``fqn``."""
        out = [(p.name, p.value, p.location, "scope" if p.from_scope else "inline")
               for p in launched.params]
        for file in launched.param_files:
            sections = self.sections(file.path) if file.path is not None else "unresolved"
            if isinstance(sections, str) or fqn is None:
                continue
            for section in sections:
                if section.matches(fqn):
                    origin = "shared file" if section.shared else "file"
                    out.extend((n, v, loc, origin) for n, v, loc in section.settings)
        return out


def _set_values(settings: list[tuple[str, Any, Location, str]]) -> dict[str, tuple[Any, Location]]:
    """Each parameter the launch sets, with its value and where it is first set: the one
    value every setting of it agrees on, else ``None`` like a value the analysis cannot read
    — which of several settings wins depends on how launch orders sources, and a guessed
    name is worse than an unknown one."""
    out: dict[str, tuple[Any, Location]] = {}
    for name, value, location, _origin in settings:
        if name in out and out[name][0] != value:
            out[name] = (None, out[name][1])
        else:
            out.setdefault(name, (value, location))
    return out


def _named_by_parameters(entities: list[Entity], values: dict[str, tuple[Any, Location]],
                         unread: Location | None = None) -> list[Entity]:
    """The entities as the launch's parameter values name them: an entity whose name is built
    from parameters the launch sets takes the values set, and the defaults in code of the
    parts it does not set (unknown when a value is no single string, or a part it does not
    set has no known default).  The alternatives of a partly known default collapse into
    the one entity the values name.

    ``unread``: where the launch hands the node a parameter file the analysis cannot read (not
    in the workspace, a name it cannot resolve): that file may set any parameter, so a name
    built from parameters the readable settings leave alone is unknown, not its default."""
    out: list[Entity] = []
    seen: set[tuple] = set()
    for entity in entities:
        set_here = [p for p in entity.name_parameters if p in values]
        if not set_here and unread is not None and entity.name_parameters:
            renamed = replace(entity, name=None, raw_name=None, invalid=None, name_suffix=None,
                              partial=False, name_set_at=unread)
            key = (renamed.kind, renamed.location, renamed.type, None)
            if key not in seen:
                seen.add(key)
                out.append(renamed)
            continue
        if not set_here:
            out.append(entity)
            continue
        texts = [values[parameter][0] if parameter in values else text
                 for parameter, text in entity.name_template or ()]
        raw = "".join(texts) if all(isinstance(t, str) for t in texts) else None
        renamed = replace(entity, name=None, raw_name=raw, invalid=None, name_suffix=None,
                          partial=False, name_set_at=values[set_here[0]][1])
        key = (renamed.kind, renamed.location, renamed.type, raw)
        if key not in seen:
            seen.add(key)
            out.append(renamed)
    return out


def _unread_names(node: RosNode) -> list[Diagnostic]:
    """Where the launch sets a parameter that names an entity to a value the analysis cannot
    read (a launch argument, settings that disagree, a part it does not set without a
    default): the name is unknown, and the setting is named."""
    out = []
    for entity in node.entities:
        if entity.name_set_at is not None and entity.raw_name is None:
            which = ", ".join(f"'{p}'" for p in entity.name_parameters)
            out.append(Diagnostic(
                entity.name_set_at.path, entity.name_set_at.line,
                f"parameter {which} of node '{node.fqn or node.name or '?'}' names the entity at "
                f"{entity.location.short()}, but its value here is not known statically (a launch "
                "argument, settings that disagree, a part without a default, or a parameter file "
                "the analysis cannot read): the name is unknown",
                "info"))
    return out


def instantiate(root: Path, graph: RosGraph, systems: list[System]) -> None:
    """Fill ``instances`` of every system against the code-level ``graph``."""
    binder = Instantiator(root)
    for system in systems:
        binder.system(graph, system)


def _placeholder(launched: LaunchedNode) -> RosNode:
    """A launched node whose code the analysis cannot see (C++, not in the workspace): no entities."""
    node = RosNode(launched.name, launched.namespace, launched.location, None,
                   conditional=launched.conditional)
    node.launch = launch_info(launched)
    return node


def _node_key(node: RosNode) -> tuple:
    return (node.fqn or "", node.location, repr(node.launch),
            tuple((e.kind, e.name or "", e.location) for e in node.entities))


def apply_systems(graph: RosGraph, systems: list[System], placeholders: bool) -> RosGraph:
    """The code graph with every node the systems start replaced by its launched instances.

    Code nodes no system starts stay as written, and so does a started one
    with ends none of its instances has: ends that only executables no launch
    file starts create on a node class they share with launched ones (their
    ``main`` adds them), which run as written.  ``placeholders`` adds the
    launched nodes whose code is not analysed (for printing a system; the
    rules leave them out, since an entity-less node only adds unknowns).
    """
    kept: dict[int, set[Location]] = {}
    for system in systems:
        for instance in system.instances:
            kept.setdefault(id(instance.code), set()).update(e.location for e in instance.node.entities)
    nodes: dict[tuple, RosNode] = {}
    for node in graph.nodes:
        if id(node) not in kept or any(e.location not in kept[id(node)] for e in node.entities):
            nodes.setdefault(_node_key(node), node)
    for system in systems:
        for instance in system.instances:
            nodes.setdefault(_node_key(instance.node), instance.node)
        if placeholders:
            bound = {id(i.launched) for i in system.instances}
            for launched in system.nodes:
                if launched.target.status != "found" and id(launched) not in bound:
                    node = _placeholder(launched)
                    nodes.setdefault(_node_key(node), node)
    out = RosGraph(sorted(nodes.values(), key=lambda n: (n.fqn or "", n.location, _node_key(n))),
                   list(graph.diagnostics))
    out.diagnostics = sorted(set(out.diagnostics) | {d for s in systems for d in s.problems})
    return out


class LaunchScopes:
    """Which launch systems started each node of a judged graph, and which names launch changed.

    A launch file that starts a driver in a namespace (or remaps it) is not a
    closed system: names it changed are judged within that system, and toward
    nodes it does not start they are interfaces — the namespace is a
    deployment choice, not a slip (issue 10, cause 5).
    """

    def __init__(self, systems: list[System]) -> None:
        self._systems: dict[tuple, set[str]] = {}
        self._code: dict[tuple, RosNode] = {}
        self._written: set[tuple[str, str]] = set()
        #: Namespaces (other than the root) of launched nodes whose code the analysis does not see.
        self._foreign: set[str] = set()
        for system in systems:
            bound = {id(instance.launched) for instance in system.instances}
            self._foreign.update(
                launched.namespace.rstrip("/") + "/" for launched in system.nodes
                if launched.target.status not in ("found", "missing-executable") and id(launched) not in bound
                and launched.namespace is not None and launched.namespace.strip("/")
                and not launched.is_unresolved("namespace"))
            for instance in system.instances:
                key = _node_key(instance.node)
                self._systems.setdefault(key, set()).add(system.launch_file)
                self._code.setdefault(key, instance.code)
                self._written.update((e.kind, e.name) for e in instance.code.entities
                                     if e.name is not None)

    def in_foreign_namespace(self, name: str | None) -> bool:
        """Whether ``name`` lies in the namespace a launch file starts a node of unseen code in
        (an installed package's executable, a C++ one not tied to code): that program's relative
        names land there, so the name is its interface."""
        return name is not None and any(name.startswith(ns) for ns in self._foreign)

    def written_name(self, kind: str, name: str) -> bool:
        """Whether a launched node's code, as written (run without its launch file), uses ``name``."""
        return (kind, name) in self._written

    def systems_of(self, node: RosNode) -> frozenset[str]:
        """The launch files whose systems start ``node`` (empty for a node as written in code)."""
        if node.launch is None:
            return frozenset()
        return frozenset(self._systems.get(_node_key(node), ()))

    def renamed(self, node: RosNode, entity: Entity) -> bool:
        """Whether launch gave ``entity`` (of the launched ``node``) a name its code does not have."""
        code = self._code.get(_node_key(node)) if node.launch is not None else None
        if code is None:
            return False
        return all(e.name != entity.name for e in code.entities
                   if e.kind == entity.kind and e.location == entity.location)

    def together(self, a: RosNode, b: RosNode) -> bool:
        """Whether the two nodes run together as far as launch says: both as written in code, or
        started by one launch system."""
        first, second = self.systems_of(a), self.systems_of(b)
        if not first and not second:
            return True
        return bool(first & second)

    @staticmethod
    def one_robot(a: RosNode, b: RosNode) -> bool:
        """Whether launch files start both nodes in one namespace other than the root (the
        robot's ``/alfie``): the bring-up and the teleop launch file of one robot, whose names
        are meant to meet there even when each launch file runs on its own."""
        return a.launch is not None and b.launch is not None and a.namespace is not None \
            and a.namespace.strip("/") != "" and a.namespace == b.namespace
