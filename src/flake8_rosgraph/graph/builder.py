"""From analysis effects to the ROS computation graph.

This is where ROS meaning enters: the analyser reports opaque effects declared by
the stubs ("node", "publisher", "timer", …) with abstract argument values; here
they become nodes and entities.  A node is one creation site × one possible
(name, namespace); an entity attaches to every node its ``node`` argument may be.
Names are expanded and validated with rcl's rules (:mod:`.names`); a value the
analysis could not pin down becomes ``None`` ("unknown"), and a value with several
possibilities yields one entity per possibility.  An unknown name that is known to
include some constants (``param if launched else '/scan'``) yields one entity per
constant, marked ``partial``, beside the unknown one: the graph names what it can and
keeps the unknown an unknown.  A type argument that may be one of several message
classes yields one entity per class — when the name is one: with several names and
several types, which goes with which is unknown, and the type stays unknown.
"""
from __future__ import annotations

import re
from typing import Any, Iterable, Sequence

from ..absint.engine import Analysis, Effect
from ..absint.objects import analysed_user_bases
from ..absint.passed_in import passed_in_parameter
from ..absint.values import (Atom, BoundMethod, ClassAtom, Const, Extern, ExternBound, FuncAtom, Input,
                             Joined, Obj, Record, Seq, Slot, Coll, Value, wrapped)
from . import names
from .parameter_switches import switched_off
from .ros_args import CommandLine, command_line, process_command_lines, with_process
from .site_calls import SiteCalls
from .model import Diagnostic, Entity, Location, RosGraph, RosNode
from .unseen_calls import HELD, SELF, helpers_handed, names_handed_to_unseen_code
from .usage_builder import build_usage

#: Effect kind → graph entity kind (JSON list name) and the argument holding its name.
ENTITY_KINDS: dict[str, tuple[str, str]] = {
    "publisher": ("publishers", "topic"),
    "subscription": ("subscriptions", "topic"),
    "service": ("services", "name"),
    "client": ("clients", "name"),
    "action_server": ("action_servers", "name"),
    "action_client": ("action_clients", "name"),
}
_INTERFACE = re.compile(r"^([A-Za-z_][\w]*)\.(msg|srv|action)(?:\.[\w.]*)?\.([A-Za-z_]\w*)$")
_POLICY_PREFIX = re.compile(r"^(RMW_QOS_POLICY_[A-Z]+_)")
QOS_POLICIES = ("history", "reliability", "durability", "liveliness")
QOS_NUMBERS = ("depth",)
QOS_DURATIONS = ("deadline", "lifespan", "liveliness_lease_duration")


_NONE = Const.of(None)


def interface_types(value: Value) -> list[str | None]:
    """``std_msgs.msg.String`` (or ``"std_msgs/msg/String"``) → ``["std_msgs/msg/String"]``;
    one type per possibility (``Twist if stamped else TwistStamped``), ``[None]`` when any
    possibility is not an interface the graph can name.

    ``None`` or a workspace class beside a type is the fallback of an import that failed
    (``except ImportError: Twist = None``, or a stand-in class with the message's constants):
    no entity exists with it — rclpy refuses a type without type support — so the entity
    that exists has the type."""
    found = set()
    for atom in value:
        if atom == _NONE or isinstance(atom, ClassAtom):
            continue
        if isinstance(atom, Extern):
            match = _INTERFACE.match(atom.qualname)
            if match:
                found.add(f"{match.group(1)}/{match.group(2)}/{match.group(3)}")
                continue
        if isinstance(atom, Const) and isinstance(atom.value, str) and atom.value.count("/") == 2:
            found.add(atom.value)
            continue
        return [None]
    return sorted(found) if found else [None]


#: Entity kind -> the interface kind its type is (``std_msgs/msg/String`` for a publisher).
_INTERFACE_KINDS = {"publishers": "msg", "subscriptions": "msg", "services": "srv", "clients": "srv",
                    "action_servers": "action", "action_clients": "action"}


def fitting_types(types: list[str | None], kind: str) -> list[str | None]:
    """The possible types of an entity of ``kind`` among ``types``: a name the code can only
    take from one of several star-imported interface modules (``from arm_msgs.msg import *``
    and ``from arm_msgs.srv import *``) is the service for a client and the message for a
    publisher. When none fits (a mistake in the code), all are kept, as written."""
    wanted = _INTERFACE_KINDS[kind]
    fits = [t for t in types if t is not None and t.split("/")[1] == wanted]
    return fits if fits and None not in types else types


def _policy(value: Value | None) -> str | None:
    """A QoS policy as its lower-case name (``ReliabilityPolicy.BEST_EFFORT``, the deprecated
    ``RMW_QOS_POLICY_RELIABILITY_BEST_EFFORT``, ``"best_effort"``); ``None`` when unknown,
    ambiguous, or only an overridable default (a parameter may change it)."""
    if value is None or value.is_top or value.soft:
        return None
    out = set()
    for atom in value:
        if isinstance(atom, Const) and isinstance(atom.value, str):
            out.add(atom.value.lower())
        elif isinstance(atom, Extern):
            last = atom.qualname.rsplit(".", 1)[-1]
            out.add(_POLICY_PREFIX.sub("", last).lower())
        else:
            return None
    return out.pop() if len(out) == 1 else None


def _number(value: Value | None) -> float | int | None:
    consts = value.consts() if value is not None and not value.soft else None
    if not consts or len(consts) != 1 or isinstance(consts[0], bool) \
            or not isinstance(consts[0], (int, float)):
        return None
    return consts[0]


def _seconds(value: Value | None) -> float | int | None:
    """A duration in seconds: a number, or a duration record (``Duration(seconds=…,
    nanoseconds=…)``, whose stub names the parts ``sec`` and ``nanosec``)."""
    atoms_ = list(value) if value is not None and not value.is_top else []
    if len(atoms_) == 1 and isinstance(atoms_[0], Record):
        sec, nanosec = _number(atoms_[0].field("sec")), _number(atoms_[0].field("nanosec"))
        return None if sec is None or nanosec is None else sec + nanosec / 1e9
    return _number(value)


def _profile(atom: Atom, depth_profile: Value | None) -> dict[str, Any] | None:
    """One possible QoS argument as the policies known statically (``None``: not a profile)."""
    if isinstance(atom, Const) and isinstance(atom.value, int) and not isinstance(atom.value, bool):
        # A plain depth: the library makes its default profile with that depth.
        base = qos_of(depth_profile) if depth_profile is not None else None
        out = {k: v for k, v in (base or {}).items() if k != "profile"}
        out["depth"] = atom.value
        return out
    if not isinstance(atom, Record):
        return None
    out: dict[str, Any] = {}
    for key in QOS_POLICIES:
        policy = _policy(atom.field(key))
        if policy is not None:
            out[key] = policy
    for key in QOS_NUMBERS:
        number = _number(atom.field(key))
        if number is not None:
            out[key] = number
    for key in QOS_DURATIONS:
        seconds = _seconds(atom.field(key))
        if seconds is not None:
            out[key] = seconds
    profile = atom.field("profile")
    if profile is not None and profile.strings() and len(profile.strings()) == 1:
        out["profile"] = profile.strings()[0]
    return out


def qos_of(value: Value, depth_profile: Value | None = None) -> dict[str, Any] | None:
    """A QoS argument as a dict of the policies known statically (``None``: nothing known).

    A plain depth is ``depth_profile`` (the profile the library makes of a depth) with
    that depth.  With several possible profiles, a policy is known when all agree on it.
    An overridable default (a profile chosen by a parameter) is not known.
    """
    if value.is_top or value.is_bottom or value.soft:
        return None
    profiles = [_profile(atom, depth_profile) for atom in value]
    if any(p is None for p in profiles):
        return None
    first, *rest = profiles
    return {k: v for k, v in first.items() if all(p.get(k) == v for p in rest)}


def json_value(value: Value) -> Any:
    """A parameter default as JSON (``None`` when not a single known constant/list)."""
    atoms_ = list(value)
    if value.is_top or len(atoms_) != 1:
        return None
    atom = atoms_[0]
    if isinstance(atom, Const) and isinstance(atom.value, (str, int, float, bool)):
        return atom.value
    if isinstance(atom, Seq):
        items = [json_value(v) for v in atom.items]
        return None if any(i is None for i in items) else items
    return None


def _choices(value: Value) -> list[str | None]:
    """Every possible string, or ``[None]`` when the value is not a known set of strings."""
    strings = value.strings()
    return list(strings) if strings else [None]


def _name_choices(value: Value) -> list[tuple[str | None, bool]]:
    """Every possible name with whether it is only *partly* known: the strings an unknown
    was joined with (``param if launched else '/scan'``), listed beside the unknown
    (``None``) that stands for the rest."""
    hinted = [h for h in value.hinted() if isinstance(h, str)]
    if hinted:
        return [(h, True) for h in hinted] + [(None, False)]
    return [(c, False) for c in _choices(value)]


def unpaired_types(eff: Effect) -> list[str]:
    """The types an entity may have when its call has several names too (a name -> type
    table iterated in one loop): which goes with which is not known, and every pairing
    would invent wrong entities, so the graph leaves the type unknown. Empty otherwise."""
    kind, name_arg = ENTITY_KINDS[eff.kind]
    types = fitting_types(interface_types(eff.arg("type")), kind)
    if len(types) > 1 and len(_name_choices(eff.arg(name_arg))) > 1:
        return [t for t in types if t is not None]
    return []


class GraphBuilder:
    def __init__(self, analysis: Analysis) -> None:
        self.analysis = analysis
        self.program = analysis.program
        self.nodes: dict[tuple, RosNode] = {}          # (location, name, namespace) -> node
        self.by_object: dict[str, list[RosNode]] = {}  # allocation site -> nodes it may be
        self.remaps: dict[int, tuple[names.RemapRule, ...]] = {}  # id(node) -> its cli_args rules
        self.process_args: dict[Effect, CommandLine] = {}  # node effect -> its rclpy.init arguments
        self._unseen: dict[int, tuple[str, ...]] = {}  # class id -> its names handed to unseen code
        self._by_short_name: dict[str, list[int]] | None = None
        self._workspace_tops = frozenset(name.split(".", 1)[0] for name in self.program.modules)
        self._code_called: dict[str, bool] = {}  # passed-in site -> its function runs on callers' nodes too

    def build(self) -> RosGraph:
        effects = self.analysis.all_effects()
        self.process_args = process_command_lines(self.analysis)
        for eff in effects:
            if eff.kind == "node":
                self._add_node(eff)
        for eff in effects:
            if "unresolved_base" in dict(eff.args):
                self._add_presumed_node(eff)
            elif eff.kind in ENTITY_KINDS or eff.kind == "timer":
                self._add_passed_in_node(eff)
        entities: dict[int, dict[tuple, Entity]] = {}
        calls = SiteCalls()
        for eff in effects:
            for node in self._owners(eff):
                bucket = entities.setdefault(id(node), {})
                made = self._entities(eff, node)
                calls.add(node, made)
                for entity in made:
                    bucket.setdefault(_entity_order(entity), entity)
        graph = RosGraph()
        for node in self.nodes.values():
            bucket = entities.get(id(node), {})
            node.entities = [calls.marked(node, bucket[k]) for k in sorted(bucket)]
            graph.nodes.append(node)
        graph.nodes.sort(key=lambda n: (n.fqn or "", n.location))
        try:
            graph.usage = build_usage(self.analysis, self._node_labels(), self._shared_sites())
        except Exception as exc:  # a defect there must cost the misuse rules only, not the graph
            graph.diagnostics.append(Diagnostic("", 0, "rclpy usage facts not extracted: internal "
                                                       f"error: {type(exc).__name__}: {exc}", "error"))
        return graph

    def _shared_sites(self) -> frozenset[str]:
        """Node object sites that stand for several nodes: the analysis' bound on contexts
        merged the objects of several creations (``Connector('a')``, ``Connector('b')``, … built
        through one factory), so two calls on "the" object may be calls on two nodes."""
        return frozenset(site for site, nodes in self.by_object.items() if len(nodes) > 1)

    def _node_labels(self) -> dict[str, str]:
        """Node object site -> how messages name it (its name(s), or its class)."""
        out = {}
        for site, nodes in self.by_object.items():
            shown = sorted({n.fqn or n.name or n.cls or "?" for n in nodes})
            out[site] = " or ".join(f"'{s}'" for s in shown)
        return out

    # -- nodes ------------------------------------------------------------------------------
    def _add_node(self, eff: Effect) -> None:
        location = Location(eff.path, eff.line, eff.column)
        namespaces = eff.arg("namespace")
        ns_choices: Iterable[str | None]
        if namespaces.consts() == [None]:
            ns_choices = ["/"]
        else:
            ns_choices = [None if ns is None else names.normalize_namespace(ns)
                          for ns in _choices(namespaces)]
        cli = with_process(command_line(eff.arg("cli_args")), self.process_args.get(eff))
        name_choices = _choices(eff.arg("name"))
        if cli.name is not None:
            name_choices = [cli.name]
        if cli.namespace is not None:
            ns_choices = [names.normalize_namespace(cli.namespace)]
        for obj in eff.arg("target"):
            if not isinstance(obj, Obj):
                continue
            for name in name_choices:
                for ns in ns_choices:
                    key = (location, name, ns)
                    node = self.nodes.get(key)
                    if node is None:
                        node = self.nodes[key] = RosNode(
                            name, ns, location, _class_name(self.program, obj),
                            conditional=eff.conditional, cls_path=_class_path(self.program, obj),
                            invalid=_node_problem(name, ns),
                            local_overrides=cli.overrides, unseen_names=self._unseen_names(obj))
                    if cli.remaps:
                        self.remaps[id(node)] = cli.remaps
                    known = self.by_object.setdefault(obj.site, [])
                    if all(n is not node for n in known):
                        known.append(node)

    def _unseen_names(self, obj: Obj) -> tuple[str, ...]:
        """The names the node's class hands, with itself, to code neither analysed nor modelled."""
        if not isinstance(obj.cls, ClassAtom):
            return ()
        cid = obj.cls.cid
        if cid not in self._unseen:
            found: set[str] = set()
            # The class and its workspace bases hand over ``self``; a workspace helper class it
            # hands itself to (``MovementCommands(self)``) hands over what it holds.
            todo: list[tuple[int, str]] = [(cid, SELF)]
            done: set[tuple[int, str]] = set()
            while todo:
                cur, receiver = todo.pop()
                if (cur, receiver) in done:
                    continue
                done.add((cur, receiver))
                klass = self.program.classes[cur]
                tree = klass.module.tree
                found.update(names_handed_to_unseen_code(klass.node, tree, self._seen, receiver))
                todo.extend((base, receiver) for base in analysed_user_bases(self.analysis.heap, cur))
                if receiver == SELF:
                    todo.extend((helper, HELD) for name in helpers_handed(klass.node)
                                for helper in self._classes_named().get(name, ()))
            self._unseen[cid] = tuple(sorted(found))
        return self._unseen[cid]

    def _classes_named(self) -> dict[str, list[int]]:
        """Workspace classes by their own name (the last part of the qualified name)."""
        if self._by_short_name is None:
            self._by_short_name = {}
            for klass in self.program.classes:
                self._by_short_name.setdefault(klass.qualname.rsplit(".", 1)[-1], []).append(klass.cid)
        return self._by_short_name

    def _seen(self, callee: str) -> bool:
        """Whether the analysis sees into ``callee``: workspace code, or a modelled library."""
        top = callee.split(".", 1)[0]
        return top in self._workspace_tops or top == "rclpy" or self.analysis.library.knows(callee)

    def _add_presumed_node(self, eff: Effect) -> None:
        """The node an object of a class with an unresolved base is presumed to be, when the
        analysis took a call on it for rclpy's (``unresolved_base`` in the effect): one per
        class, of unknown name and namespace, located at its class definition."""
        base = (eff.arg("unresolved_base").strings() or [None])[0]
        for obj in eff.arg("node"):
            if not isinstance(obj, Obj) or not isinstance(obj.cls, ClassAtom) or obj.site in self.by_object:
                continue
            klass = self.program.classes[obj.cls.cid]
            location = Location(klass.module.path, klass.node.lineno, klass.module.column(klass.node))
            node = self.nodes.get((location, None, None))
            if node is None:
                node = self.nodes[(location, None, None)] = RosNode(
                    None, None, location, klass.qualname, cls_path=klass.module.path, unresolved_base=base)
            self.by_object[obj.site] = [node]

    def _add_passed_in_node(self, eff: Effect) -> None:
        """The node a function's parameter stands for when no analysed caller passes one (see
        :mod:`~flake8_rosgraph.absint.passed_in`): one per parameter, of unknown name and
        namespace, located at the function. None when analysed code calls the function after
        all (an entry whose name some code reads runs alongside its callers): the node is
        then the one the callers pass."""
        for obj in eff.arg("node"):
            found = passed_in_parameter(obj.site) if isinstance(obj, Obj) else None
            if found is None or obj.site in self.by_object or self._called_by_code(found[0], obj.site):
                continue
            func = self.program.functions[found[0]]
            location = Location(func.module.path, func.node.lineno, func.module.column(func.node))
            # Keyed by the parameter: two nodes handed to one function are two nodes.
            self.by_object[obj.site] = [self.nodes.setdefault((location, None, obj.site), RosNode(
                None, None, location, passed_in=f"parameter `{found[1]}` of {func.qualname}"))]

    def _called_by_code(self, fid: int, site: str) -> bool:
        """Whether function ``fid`` also ran on arguments analysed code gave: a run whose
        arguments do not hold the passed-in object of ``site`` (asked once per site)."""
        if site not in self._code_called:
            self._code_called[site] = any(task[0] == "fn" and task[1] == fid and not any(
                isinstance(a, Obj) and a.site == site for v in task[2] if not v.is_top for a in v)
                for task in self.analysis.effects)
        return self._code_called[site]

    def _owners(self, eff: Effect) -> list[RosNode]:
        if eff.kind == "node":
            return []
        out: list[RosNode] = []
        for obj in eff.arg("node"):
            if isinstance(obj, Obj):
                out.extend(n for n in self.by_object.get(obj.site, ())
                           if all(n is not o for o in out))
        return out

    # -- entities ---------------------------------------------------------------------------
    def _entities(self, eff: Effect, node: RosNode) -> list[Entity]:
        location = Location(eff.path, eff.line, eff.column)
        common = dict(location=location, conditional=eff.conditional)
        if switched_off(eff):
            return []
        if eff.kind in ENTITY_KINDS:
            kind, name_arg = ENTITY_KINDS[eff.kind]
            types = fitting_types(interface_types(eff.arg("type")), kind)
            qos = qos_of(eff.arg("qos"), dict(eff.args).get("qos_for_depth")) \
                if kind in ("publishers", "subscriptions") else None
            callback = self.callback_name(eff.arg("callback")) if "callback" in dict(eff.args) \
                else None
            via = eff.arg("via").strings()
            out = []
            written = dict(eff.texts).get(name_arg)
            choices = _name_choices(eff.arg(name_arg))
            if unpaired_types(eff):
                types = [None]
            template = _name_template(eff.arg(name_arg), eff.arg("node"))
            for raw, partial in choices:
                name, problem = self._resolve(raw, node)
                if partial and problem:
                    # A guard the analysis does not decide on a partly known value
                    # (``if topic:`` after ``topic = param or ''``) keeps it from the call.
                    continue
                suffix = names.known_suffix(raw) if name is None and not self.remaps.get(id(node)) \
                    else None
                out.extend(Entity(kind, name, raw_name=raw, type=type_, qos=qos, callback=callback,
                                  invalid=problem, via=via[0] if via else None, name_text=written,
                                  name_suffix=suffix, partial=partial, name_template=template,
                                  **common)
                           for type_ in types)
            return out
        if eff.kind == "timer":
            callback = self.callback_name(eff.arg("callback"))
            periods = eff.arg("period").consts()
            if not periods or not all(isinstance(p, (int, float)) and not isinstance(p, bool)
                                      for p in periods):
                periods = [None]
            return [Entity("timers", None, period=None if p is None else float(p),
                           callback=callback, **common) for p in periods]
        if eff.kind == "parameter":
            default = json_value(eff.arg("default"))
            return [Entity("parameters", n, raw_name=n, default=default,
                           invalid=_param_problem(n), partial=partial, **common)
                    for n, partial in _name_choices(eff.arg("name"))
                    if not (partial and _param_problem(n))]  # as for names above
        if eff.kind == "parameters":
            return self._declared_parameters(eff, common)
        return []

    def _declared_parameters(self, eff: Effect, common: dict) -> list[Entity]:
        prefixes = _choices(eff.arg("namespace"))
        out: list[Entity] = []
        for atom in eff.arg("parameters"):
            items = atom.items if isinstance(atom, Seq) else \
                (atom.elem,) if isinstance(atom, Coll) else ()
            for item in items:
                for entry in item:
                    if not isinstance(entry, Seq) or not entry.items:
                        continue
                    default = json_value(entry.items[1]) if len(entry.items) > 1 else None
                    for name in _choices(entry.items[0]):
                        for prefix in prefixes:
                            full = None if name is None or prefix is None else \
                                (f"{prefix}.{name}" if prefix else name)
                            out.append(Entity("parameters", full, raw_name=full, default=default,
                                              invalid=_param_problem(full), **common))
        return out

    def _resolve(self, raw: str | None, node: RosNode) -> tuple[str | None, str | None]:
        return resolve_name(raw, node, self.remaps.get(id(node), ()))

    def callback_name(self, value: Value) -> str | None:
        found = []
        for atom in map(wrapped, value):
            if isinstance(atom, (FuncAtom, BoundMethod)):
                found.append(self.program.functions[atom.fid].qualname)
            elif isinstance(atom, ExternBound):
                found.append(".".join(atom.qualname.split(".")[-2:]))
        return sorted(found)[0] if found else None


def resolve_name(raw: str | None, node: RosNode,
                 remaps: Sequence[names.RemapRule] = ()) -> tuple[str | None, str | None]:
    """A written topic/service/action name expanded on ``node`` per rcl (and the node's own
    ``cli_args`` remaps), and why it is invalid (if so).

    Unknown (``None``) when the name is, or when it is relative and the node's namespace is (or
    it is private and the node's name is); a relative name depends on the namespace only.
    """
    if raw is None:
        return None, None
    if node.name is None or node.namespace is None:
        if raw.startswith("/"):
            check = names.validate_full_topic_name(raw)
            return raw, None if check.ok else check.reason
        if node.namespace is None or raw.startswith("~") or "{node}" in raw:
            return None, None
        # A relative name depends on the namespace only: an unknown node name (a
        # placeholder stands for it) must not make it unknown.
        expanded, check = names.expand_topic_name(raw, "unknown", node.namespace)
        if expanded is None:
            return raw, check.reason
        return expanded, None if check.ok else check.reason
    expanded, check = names.expand_topic_name(raw, node.name, node.namespace)
    if expanded is None:
        return raw, check.reason
    rule = names.first_remap_match(expanded, remaps, node.name, node.namespace)
    if rule is not None:
        expanded, check = names.expand_topic_name(rule.replacement, node.name, node.namespace)
        if expanded is None:
            return rule.replacement, check.reason
    return expanded, None if check.ok else check.reason


#: The key under which the rclpy stub keeps a node's parameter (``param:{name}``).
_PARAMETER_KEY = "param:"


def _name_template(name: Value, node: Value) -> tuple[tuple[str, str | None], ...] | None:
    """The name as text and parameters of the creating node, if it is built from them (the
    stubs mark a parameter's value as the outside input ``param:NAME`` of its node object);
    ``None`` when it is not, or when a part is another object's input (launch sets that
    node's parameters, not this one's).  See :attr:`Entity.name_template`."""
    origin = name.origin
    if isinstance(origin, Input):
        strings = name.strings()
        slots: tuple = (Slot(origin, strings[0] if strings and len(strings) == 1 else None),)
    else:
        slots = origin.parts if isinstance(origin, Joined) else ()
    holders = {obj.site for obj in node if isinstance(obj, Obj)}
    out: list[tuple[str, str | None]] = []
    for part in slots:
        if isinstance(part, str):
            out.append(("", part))
        elif part.input.holder in holders and part.input.key.startswith(_PARAMETER_KEY):
            out.append((part.input.key[len(_PARAMETER_KEY):], part.default))
        else:
            return None
    return tuple(out) if any(parameter for parameter, _ in out) else None


def _class_name(program, obj: Obj) -> str | None:
    if isinstance(obj.cls, ClassAtom):
        return program.classes[obj.cls.cid].qualname
    return None


def _class_path(program, obj: Obj) -> str | None:
    """The file defining ``obj``'s class, for a workspace class."""
    if isinstance(obj.cls, ClassAtom):
        return program.classes[obj.cls.cid].module.path
    return None


def _node_problem(name: str | None, ns: str | None) -> str | None:
    if name is not None:
        check = names.validate_node_name(name)
        if not check.ok:
            return f"node name '{name}' {check.reason}"
    if ns is not None:
        check = names.validate_namespace(ns)
        if not check.ok:
            return f"namespace '{ns}' {check.reason}"
    return None


def _param_problem(name: str | None) -> str | None:
    if name is None:
        return None
    check = names.validate_parameter_name(name)
    return None if check.ok else check.reason


def _entity_order(e: Entity) -> tuple:
    """Sort key that is also the identity of an entity on its node."""
    return (e.location, e.kind, e.name or "", e.raw_name or "", e.period or 0.0, repr(e.default),
            e.callback or "", e.type or "", repr(sorted((e.qos or {}).items())), e.conditional,
            e.invalid or "", e.via or "", e.partial, _template_order(e.name_template))


def _template_order(template: tuple[tuple[str, str | None], ...] | None) -> tuple:
    """A name template as a sort key: a part without a known default (``None``) sorts before
    every text, so that two templates that differ only there compare (muto's commands node:
    a parameter declared inside ``try`` has a default on one path and none on the other)."""
    return tuple((parameter, default is not None, default or "") for parameter, default in template or ())


def build_graph_from(analysis: Analysis) -> RosGraph:
    return GraphBuilder(analysis).build()
