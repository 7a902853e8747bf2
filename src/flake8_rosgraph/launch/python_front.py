"""Python launch files → :mod:`.actions`, from the abstract interpreter's results.

A ``*.launch.py`` file is analysed like any other module (it imports
``launch``/``launch_ros``, whose stubs make it relevant); its
``generate_launch_description()`` is an entry function, and its return
summary is the ``LaunchDescription`` object.  The stubs make every action an
object whose constructor stores its arguments on the object (so the action
keeps its call site, ``path:line:col``) and every substitution a record; this
module reads that heap back into the neutral action tree.  Nothing is
executed: values the analysis could not pin down become
:class:`~.actions.Unknown` with a reason.
"""
from __future__ import annotations

import re
import weakref
from typing import Any, Iterable

from ..absint.engine import Analysis
from ..absint.values import (BOTTOM, Coll, Const, DictAtom, Extern, FuncAtom, Obj, Record, Seq, Value,
                             join_all)
from ..graph.model import Location
from .actions import (Action, Condition, DeclareArgument, GroupAction, Include, Join, NodeAction,
                      PkgShare, PushNamespace, SetConfiguration, SetParameter, SetRemap, Subst, Text,
                      ThisDir, Unknown, Unsupported, Var)

ENTRY_FUNCTION = "generate_launch_description"

_LD = "launch.launch_description.LaunchDescription"
_NODE = "launch_ros.actions.node.Node"
_LIFECYCLE = "launch_ros.actions.lifecycle_node.LifecycleNode"
_SOURCES = {
    "launch.launch_description_sources.python_launch_description_source.PythonLaunchDescriptionSource",
    "launch.launch_description_sources.any_launch_description_source.AnyLaunchDescriptionSource",
    "launch.launch_description_sources.frontend_launch_description_source.FrontendLaunchDescriptionSource",
}
_PKG_SHARE = {"launch_ros.substitutions.find_package.FindPackageShare",
              "ament_index_python.packages.get_package_share_directory"}
#: Actions that start nothing and change no scope: skipped silently.
#: Launch actions that start no node and change no name: skipped, the system stays complete.
_INERT = frozenset({"LogInfo", "SetEnvironmentVariable", "AppendEnvironmentVariable",
                    "UnsetEnvironmentVariable", "PrependEnvironmentVariable", "Shutdown",
                    "SetROSLogDir", "EmitEvent"})


#: A call site: ``path:line:col``, with ``@<context index>`` appended inside functions.
#: The path may itself hold ``@`` and ``:``, so the numbers are taken from the end.
_SITE = re.compile(r"^(.*):(\d+):(\d+)(?:@\d+)?$", re.DOTALL)


def _site_location(site: str) -> Location:
    """``path:line:col`` (``@context`` appended inside functions) → a 1-based location."""
    match = _SITE.match(site)
    if match is None:
        raise ValueError(f"not a call site: {site!r}")
    return Location(match.group(1), int(match.group(2)), int(match.group(3)) + 1)


def launch_description(analysis: Analysis, path: str) -> Value | None:
    """The joined return summary of ``generate_launch_description`` in the module at ``path``."""
    tasks = _entry_tasks(analysis).get(path)
    if tasks is None:
        return None
    return join_all(analysis.heap.get(("ret", task), BOTTOM) for task in tasks)


#: Per analysis: (its task runs when indexed, module path → the tasks of its entry functions).
_ENTRY_TASKS: "weakref.WeakKeyDictionary[Analysis, tuple[int, dict[str, list]]]" = weakref.WeakKeyDictionary()


def _entry_tasks(analysis: Analysis) -> dict[str, list]:
    """Module path → the tasks of its module-level ``generate_launch_description`` functions,
    in the order of ``analysis.effects`` (an empty list for a module that has the function but
    no task of it). Indexed once per analysis, not once per launch file."""
    known = _ENTRY_TASKS.get(analysis)
    if known is not None and known[0] == analysis.task_runs:
        return known[1]
    path_of = {f.fid: f.module.path for f in analysis.program.functions
               if f.parent is None and f.cls is None and f.qualname == ENTRY_FUNCTION}
    index: dict[str, list] = {path: [] for path in path_of.values()}
    for task in analysis.effects:
        if task[0] == "fn" and task[1] in path_of:
            index[path_of[task[1]]].append(task)
    _ENTRY_TASKS[analysis] = (analysis.task_runs, index)
    return index


def _order(atom: Any) -> tuple:
    return (atom.site if isinstance(atom, Obj) else "", repr(atom))


def _alternative(chosen: Obj, descriptions: list[Obj], actions: list[Action],
                 at: Location) -> list[Action]:
    """``actions`` of one of several descriptions the function may return (``if mode == 'a':
    return LaunchDescription([...])`` ``else: return LaunchDescription([...])``): one call returns
    one of them, so their nodes are conditional and never start together. Each alternative runs
    under "this one was returned" and "no other one was", which the guards of any two
    alternatives contradict."""
    for other in reversed(descriptions):
        if other is not chosen:
            actions = [GroupAction(at, actions, False, Condition(_returned(other), negate=True))]
    return [GroupAction(at, actions, False, Condition(_returned(chosen)))]


def _returned(description: Obj) -> Text:
    """The (never evaluated) condition that ``description`` is the one returned."""
    return Text(f"{ENTRY_FUNCTION}() returns the description made at {description.site}")


class PythonFront:
    def __init__(self, analysis: Analysis, path: str) -> None:
        self.analysis = analysis
        self.path = path

    def kind(self, atom: Any) -> str:
        if isinstance(atom, Obj) and isinstance(atom.cls, Extern):
            return self.analysis.library.canonical(atom.cls.qualname)
        if isinstance(atom, Record):
            return self.analysis.library.canonical(atom.qualname)
        return ""

    def field(self, obj: Obj, key: str) -> Value:
        return self.analysis.heap.get(("a", obj.site, key), BOTTOM)

    # -- entry --------------------------------------------------------------------------------
    def actions(self) -> tuple[list[Action], str | None]:
        """The description's actions, or an empty list and why there are none."""
        summary = launch_description(self.analysis, self.path)
        if summary is None:
            return [], f"no {ENTRY_FUNCTION}() function"
        descriptions = [a for a in summary if self.kind(a) == _LD]
        if summary.is_top or not descriptions:
            return [], f"{ENTRY_FUNCTION}() does not return a LaunchDescription the analysis can follow"
        out: list[Action] = []
        ordered = sorted(descriptions, key=_order)
        for ld in ordered:
            at = _site_location(ld.site)
            actions = self.entity_list(self.field(ld, "initial_entities"), at) + \
                self.entity_list(self.field(ld, "added_entities"), at)
            out.extend(_alternative(ld, ordered, actions, at) if len(ordered) > 1 else actions)
        return out, None

    def entity_list(self, value: Value, at: Location, listed: frozenset[Obj] = frozenset()) -> list[Action]:
        """The actions of a list of launch entities. Several lists are alternatives (the lists a
        launch function returns from the two branches of an ``if``): an action object an earlier
        alternative (or an enclosing one: ``listed``) already lists, such as the map server both
        branches start, is one action, started once, not once per alternative."""
        if value.is_top:
            return [Unsupported(at, "a list of launch entities the analysis cannot determine")]
        out: list[Action] = []
        seen = set(listed)
        for atom in sorted(value, key=_order):
            before = frozenset(seen)
            if isinstance(atom, Seq):
                for item in atom.items:
                    out.extend(self.entity_list(item, at, before))
                    seen.update(_objects(item))
            elif isinstance(atom, Coll):
                out.extend(self.entity_list(atom.elem, at, before))
                seen.update(_objects(atom.elem))
            elif isinstance(atom, Obj):
                if atom not in listed:
                    out.extend(self.action(atom))
            elif atom != Const.of(None):
                out.append(Unsupported(at, "a launch entity the analysis cannot determine"))
        return out

    # -- actions -------------------------------------------------------------------------------
    def action(self, obj: Obj) -> list[Action]:
        kind = self.kind(obj)
        at = _site_location(obj.site)
        short = kind.rsplit(".", 1)[-1]
        if kind in (_NODE, _LIFECYCLE):
            return [self.node(obj, at, kind == _LIFECYCLE)]
        if short == "GroupAction":
            scoped = self.field(obj, "scoped").consts() != [False]
            return [GroupAction(at, self.entity_list(self.field(obj, "actions"), at), scoped,
                                self.condition(obj))]
        if short == "TimerAction":
            return [GroupAction(at, self.entity_list(self.field(obj, "actions"), at), False,
                                self.condition(obj))]
        if short == "RegisterEventHandler":
            # The handler's actions run when its event comes (a process exits, starts…): launched
            # then, so conditional. A handler the stubs do not model is not followed.
            actions: list[Action] = []
            for handler in sorted(self.field(obj, "event_handler"), key=_order):
                then = self.field(handler, "on_event") if isinstance(handler, Obj) else BOTTOM
                if then.is_bottom:
                    actions.append(Unsupported(at, f"an event handler the analysis does not model "
                                                   f"({self.kind(handler).rsplit('.', 1)[-1] or '?'})"))
                else:
                    actions.extend(self.entity_list(then, at))
            return [GroupAction(at, actions, False, Condition(Unknown("when the event comes")))]
        if short == "PushRosNamespace":
            return [PushNamespace(at, self.subst(self.field(obj, "namespace")), self.condition(obj))]
        if short == "SetRemap":
            return [SetRemap(at, self.subst(self.field(obj, "src")), self.subst(self.field(obj, "dst")),
                             self.condition(obj))]
        if short == "SetParameter":
            name = self.field(obj, "name").strings()
            return [SetParameter(at, name[0], self.param_value(self.field(obj, "value")), self.condition(obj))
                    if name and len(name) == 1 else Unsupported(at, "SetParameter with an unknown name", starts_nodes=False)]
        if short in ("DeclareLaunchArgument", "SetLaunchConfiguration"):
            names = self.field(obj, "name").strings()
            if not names or len(names) != 1:
                return [Unsupported(at, f"{short} with an unknown name", starts_nodes=False)]
            if short == "SetLaunchConfiguration":
                return [SetConfiguration(at, names[0], self.subst(self.field(obj, "value")))]
            default = self.field(obj, "default_value")
            return [DeclareArgument(at, names[0], None if default.consts() == [None] else self.subst(default))]
        if short == "IncludeLaunchDescription":
            return [Include(at, self.source(self.field(obj, "launch_description_source")),
                            self.arguments(self.field(obj, "launch_arguments")), self.condition(obj))]
        if short == "OpaqueFunction":
            return self.opaque(obj, at)
        if short in ("ComposableNodeContainer", "LoadComposableNodes"):
            return self.components(obj, at)
        if short == "ExecuteProcess":
            started = self.process_node(obj, at)
            return [started] if started is not None else [Unsupported(at, "ExecuteProcess")]
        if short in _INERT and kind.split(".")[0] in ("launch", "launch_ros"):
            return []
        return [Unsupported(at, short or "an unknown launch entity")]

    def process_node(self, obj: Obj, at: Location) -> NodeAction | None:
        """The node an ``ExecuteProcess`` starts when its command is a package's executable:
        ``[ExecutableInPackage(executable=…, package=…), …]`` or ``['ros2', 'run', pkg, exe, …]``,
        with the ``--ros-args`` that follow read like a node's; ``None`` for any other program."""
        command = [atom for atom in self.field(obj, "cmd") if isinstance(atom, Seq)]
        if len(command) != 1 or not command[0].items:
            return None
        items = list(command[0].items)
        made = [a for a in items[0] if isinstance(a, Record) and self.kind(a).endswith(".ExecutableInPackage")]
        if len(made) == 1 and len(items[0].atoms or ()) == 1:
            package, executable = made[0].field("package"), made[0].field("executable")
            rest = items[1:]
        elif [v.strings() for v in items[:2]] == [["ros2"], ["run"]] and len(items) >= 4:
            package, executable = items[2], items[3]
            rest = items[4:]
        else:
            return None
        node = NodeAction(at, self.subst(package or BOTTOM), self.subst(executable or BOTTOM),
                          condition=self.condition(obj))
        words = [value.strings() for value in rest]
        if ["--ros-args"] not in words:
            return node
        if any(len(w or ()) != 1 for w in words):
            node.unresolved.append("ros_arguments: a --ros-args word the analysis cannot determine")
            return node
        _read_ros_args([w[0] for w in words][words.index(["--ros-args"]) + 1:], node, at)
        return node

    def node(self, obj: Obj, at: Location, lifecycle: bool) -> NodeAction:
        return self.node_action(lambda key: self.field(obj, key), at, lifecycle, self.condition(obj))

    def opaque(self, obj: Obj, at: Location) -> list[Action]:
        """The actions an ``OpaqueFunction``'s function returns, as the interpreter found them
        (its launch context unknown: what it reads from it is unresolved); the function's own
        ``args``/``kwargs`` are not bound."""
        functions = self.field(obj, "function")
        fids = {atom.fid for atom in functions if isinstance(atom, FuncAtom)}
        if not fids or len(fids) != len(functions.atoms or ()):
            return [Unsupported(at, "OpaqueFunction of a function the analysis cannot determine")]
        returned = BOTTOM
        for task in self.analysis.effects:
            if task[0] == "fn" and task[1] in fids:
                returned = returned.join(self.analysis.returns(task))
        if returned.is_bottom:
            return [Unsupported(at, "OpaqueFunction whose function returns no actions the analysis sees")]
        return [GroupAction(at, self.entity_list(returned, at), False, self.condition(obj))]

    def components(self, obj: Obj, at: Location) -> list[Action]:
        """A container (itself a node) and the components it loads, or those ``LoadComposableNodes``
        loads into one: each component is a node of its package, named and namespaced by its
        description (a pushed namespace applies, the container's does not), with no executable."""
        out: list[Action] = []
        condition = self.condition(obj)
        if self.kind(obj).endswith("ComposableNodeContainer"):
            out.append(self.node(obj, at, False))
        gaps = NodeAction(at, None, None)  # collects what the description list hides
        for description in self.items(self.field(obj, "composable_node_descriptions"),
                                      "composable_node_descriptions", gaps):
            if isinstance(description, Record) and self.kind(description).endswith(".ComposableNode"):
                component = self.node_action(lambda key: description.field(key) or BOTTOM, at, False,
                                             condition)
                component.executable = None
                out.append(component)
            else:
                out.append(Unsupported(at, "a composable node description the analysis cannot determine"))
        out.extend(Unsupported(at, gap) for gap in gaps.unresolved)
        return out

    def node_action(self, field: Any, at: Location, lifecycle: bool, condition: Condition | None) -> NodeAction:
        """A node action from the fields ``field(key)`` of ``Node(...)`` or ``ComposableNode(...)``."""
        def pick(*keys: str) -> Subst | None:
            for key in keys:
                value = field(key)
                if value.consts() != [None] and not value.is_bottom:
                    return self.subst(value)
            return None

        node = NodeAction(at, pick("package"), pick("executable", "node_executable"),
                          pick("name", "node_name"), pick("namespace", "node_namespace"),
                          condition=condition, lifecycle=lifecycle)
        remaps = field("remappings")
        for pair in self.items(remaps, "remappings", node):
            if isinstance(pair, Seq) and len(pair.items) == 2:
                node.remaps.append((self.subst(pair.items[0]), self.subst(pair.items[1]), at))
            else:
                node.unresolved.append("remappings: an entry is not a (from, to) pair")
        for entry in self.items(field("parameters"), "parameters", node):
            if isinstance(entry, DictAtom):
                self.inline_params(entry, "", node, at)
            elif isinstance(entry, Record) and self.kind(entry).endswith("ParameterFile"):
                node.param_files.append((self.subst(entry.field("param_file") or BOTTOM), at))
            else:
                node.param_files.append((self.subst(Value(frozenset([entry]))), at))
        if self.ros_arguments(field("ros_arguments"), field("arguments")):
            node.unresolved.append("ros_arguments: --ros-args given on the command line are not interpreted")
        return node

    @staticmethod
    def ros_arguments(ros_arguments: Value, arguments: Value) -> bool:
        """Whether the node gets ``--ros-args`` rules (remaps, parameters) the walker does not read.

        Plain ``arguments`` (``['-d', rviz_config]``) are the program's own and change nothing in
        the graph; only ``ros_arguments`` and a literal ``--ros-args`` in ``arguments`` do.
        """
        if not ros_arguments.is_bottom and ros_arguments.consts() != [None]:
            return True
        for atom in arguments:
            if isinstance(atom, Seq) and any("--ros-args" in (item.strings() or ()) for item in atom.items):
                return True
        return False

    def items(self, value: Value, what: str, node: NodeAction) -> Iterable[Any]:
        """Elements of a list argument; unknown parts go to ``node.unresolved``."""
        if value.is_bottom or value.consts() == [None]:
            return []
        if value.is_top:
            node.unresolved.append(f"{what}: not known statically")
            return []
        out: list[Any] = []
        lists = [atom for atom in value if isinstance(atom, Seq)]
        if len({len(atom.items) for atom in lists}) > 1:
            node.unresolved.append(f"{what}: one of several lists the analysis cannot choose between")
            lists = []
        # Alternatives of one list (built on two branches) are joined entry by entry, never
        # concatenated: an entry that differs between them is not known statically.
        for entry in (join_all(column) for column in zip(*(atom.items for atom in lists))):
            if entry.is_top or len(list(entry)) != 1:
                node.unresolved.append(f"{what}: an entry is not known statically")
            else:
                out.extend(entry)
        for atom in sorted(value, key=_order):
            if isinstance(atom, Seq):
                continue
            if isinstance(atom, Coll):
                node.unresolved.append(f"{what}: a list built at run time")
            else:
                node.unresolved.append(f"{what}: not a list")
        return out

    def inline_params(self, entry: DictAtom, prefix: str, node: NodeAction, at: Location) -> None:
        for key, value in entry.items:
            names = key.strings()
            if not names or len(names) != 1:
                node.unresolved.append("parameters: a name is not known statically")
                continue
            name = prefix + names[0]
            nested = [a for a in value if isinstance(a, DictAtom)]
            if nested and len(list(value)) == 1:
                self.inline_params(nested[0], name + ".", node, at)
            else:
                node.params.append((name, self.param_value(value), at))

    def param_value(self, value: Value) -> Any:
        consts = value.consts()
        if consts is not None and len(consts) == 1:
            return consts[0]
        return None

    # -- substitutions -------------------------------------------------------------------------
    def subst(self, value: Value) -> Subst:
        atoms_ = list(value)
        if value.is_top or not atoms_:
            return Unknown("a value the analysis cannot determine")
        if len(atoms_) > 1:
            return Unknown("a value with several possible values")
        atom = atoms_[0]
        if isinstance(atom, Const):
            if isinstance(atom.value, bool):
                return Text("true" if atom.value else "false")
            if isinstance(atom.value, (str, int, float)):
                return Text(str(atom.value))
            return Unknown(f"the constant {atom.value!r}")
        if isinstance(atom, Seq):
            return Join(tuple(self.subst(v) for v in atom.items))
        if isinstance(atom, Record):
            return self.record_subst(atom)
        return Unknown("a value that is not a string or substitution")

    def record_subst(self, record: Record) -> Subst:
        kind = self.kind(record)
        short = kind.rsplit(".", 1)[-1]
        if short == "LaunchConfiguration":
            names = (record.field("variable_name") or BOTTOM).strings()
            if not names or len(names) != 1:
                return Unknown("LaunchConfiguration with an unknown name")
            default = record.field("default")
            has_default = default is not None and default.consts() != [None]
            return Var(names[0], self.subst(default) if has_default and default is not None else None)
        if short == "TextSubstitution":
            return self.subst(record.field("text") or BOTTOM)
        if short == "PathJoinSubstitution":
            parts = record.field("substitutions") or BOTTOM
            joined = self.subst(parts)
            return Join(joined.parts, "/") if isinstance(joined, Join) else joined
        if kind == "os.path.join":
            parts = self.subst(record.field("paths") or BOTTOM)
            return Join(parts.parts, "/") if isinstance(parts, Join) else parts
        if short == "ThisLaunchFileDir":
            return ThisDir()
        if short == "PythonExpression":
            return Unknown("PythonExpression is not evaluated statically",
                           key=self.subst(record.field("expression") or BOTTOM))
        if kind in _PKG_SHARE:
            return PkgShare(self.subst(record.field("package") or BOTTOM))
        return Unknown(f"{short} is not evaluated statically")

    def condition(self, obj: Obj) -> Condition | None:
        value = self.field(obj, "condition")
        if value.is_bottom or value.consts() == [None]:
            return None
        for atom in sorted(value, key=_order):
            if isinstance(atom, Record):
                short = self.kind(atom).rsplit(".", 1)[-1]
                if short in ("IfCondition", "UnlessCondition"):
                    return Condition(self.subst(atom.field("predicate_expression") or BOTTOM),
                                     negate=short == "UnlessCondition")
        return Condition(Unknown("a condition the analysis does not evaluate"))

    def source(self, value: Value) -> Subst:
        sources = [atom for atom in value if isinstance(atom, Record) and self.kind(atom) in _SOURCES]
        if len(sources) > 1:  # launch description sources built on several paths
            return Unknown("one of several launch files")
        if sources:
            return self.subst(sources[0].field("launch_file_path") or BOTTOM)
        return self.subst(value)

    def arguments(self, value: Value) -> list[tuple[str, Subst]] | None:
        if value.is_bottom or value.consts() == [None]:
            return []
        atoms_ = list(value)
        if value.is_top or len(atoms_) != 1:
            return None
        atom = atoms_[0]
        pairs: list[tuple[Value, Value]] = []
        if isinstance(atom, DictAtom):
            pairs = list(atom.items)
        elif isinstance(atom, Seq):
            for item in atom.items:
                inner = list(item)
                if len(inner) != 1 or not isinstance(inner[0], Seq) or len(inner[0].items) != 2:
                    return None
                pairs.append((inner[0].items[0], inner[0].items[1]))
        elif isinstance(atom, Coll):
            # dict(...).items(): keys and values are joined; only a single pair stays readable.
            inner = list(atom.elem)
            if len(inner) != 1 or not isinstance(inner[0], Seq) or len(inner[0].items) != 2:
                return None
            pairs = [(inner[0].items[0], inner[0].items[1])]
        else:
            return None
        out: list[tuple[str, Subst]] = []
        for key, val in pairs:
            names = key.strings()
            if not names or len(names) != 1:
                return None
            out.append((names[0], self.subst(val)))
        return out


def read_python_launch(analysis: Analysis, path: str) -> tuple[list[Action], str | None]:
    """The actions of the Python launch file at ``path`` (root-relative), or why there are none."""
    return PythonFront(analysis, path).actions()


def _read_ros_args(words: list[str], node: NodeAction, at: Location) -> None:
    """``-r from:=to`` (``__ns``/``__node`` set the namespace and name), ``-p name:=value`` and
    ``--params-file FILE`` of a command line, into ``node``; anything else is noted unresolved."""
    pairs = iter(words)
    for flag in pairs:
        if flag == "--":
            return
        value = next(pairs, None)
        if value is None or flag not in ("-r", "--remap", "-p", "--param", "--params-file"):
            node.unresolved.append(f"ros_arguments: '{flag}' is not interpreted")
            continue
        if flag == "--params-file":
            node.param_files.append((Text(value), at))
            continue
        key, sep, target = value.partition(":=")
        if not sep:
            node.unresolved.append(f"ros_arguments: '{value}' is not a name:=value rule")
        elif flag in ("-p", "--param"):
            node.params.append((key, _scalar(target), at))
        elif key == "__ns":
            node.namespace = Text(target)
        elif key in ("__node", "__name"):
            node.name = Text(target)
        else:
            node.remaps.append((Text(key), Text(target), at))


def _scalar(text: str) -> Any:
    """A ``-p name:=value`` value as rcl reads it (YAML): a bool, an int, a float or a string."""
    lowered = text.lower()
    if lowered in ("true", "false"):
        return lowered == "true"
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def _objects(value: Value) -> set[Obj]:
    """The heap objects among the atoms of ``value``."""
    return {atom for atom in value if isinstance(atom, Obj)}
