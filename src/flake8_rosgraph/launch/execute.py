"""Launch semantics: run an action tree in scopes, as ``ros2 launch`` would, without running anything.

What each action does to the scope follows launch / launch_ros:
``DeclareLaunchArgument`` sets a default only when no value was passed;
``<let>``/``SetLaunchConfiguration`` overrides; a scoped ``GroupAction``
copies the scope for its children; ``PushRosNamespace`` prefixes a relative
namespace onto the pushed one (``launch_ros.utilities.prefix_namespace``);
``SetRemap``/``SetParameter`` apply to every later node in the scope, before
the node's own remaps and parameters; ``IncludeLaunchDescription`` runs the
included file in a copy of the scope with its ``launch_arguments`` set; a
node's ``namespace`` is prefixed by the pushed one unless absolute.

Includes across packages resolve inside the workspace (``find-pkg-share``
maps to the package's source folder; a file installed under another
sub-folder is found by name when that name is unique in the package).  What
cannot be resolved is a :class:`~flake8_rosgraph.graph.model.Diagnostic` on
the system, not a guess.
"""
from __future__ import annotations

import posixpath
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Callable

from ..graph.model import Diagnostic, Location
from .actions import (Action, Condition, DeclareArgument, GroupAction, Include, Join, NodeAction,
                      PkgShare, PushNamespace, SetConfiguration, SetParameter, SetRemap, Subst, Text,
                      ThisDir, Unknown, Unsupported, Var)
from .model import ExecutableRef, Guard, LaunchedNode, ParamFileRef, ParamValue, Remap, System
from .frontend_subst import parse_substitutions
from .packages import PackageIndex
from .yaml_reader import scalar

#: Include depth at which a (probably recursive) include chain is cut.
MAX_INCLUDE_DEPTH = 16
#: Launch files one system may run in total (counting each inclusion): bounds include fan-out,
#: where 16 files each including the next one 8 times would otherwise run 8**15 files.
MAX_INCLUDED_FILES = 512


class Unresolved(Exception):
    """A substitution without a static value; the message says why."""


@dataclass
class Scope:
    file: str
    configs: dict[str, str | None] = field(default_factory=dict)
    #: Launch arguments came from an include whose argument list is unknown.
    opaque: bool = False
    namespace: str | None = None          # the pushed ROS namespace, ``None``: none pushed
    namespace_unknown: str | None = None  # why the pushed namespace is unknown
    remaps: list[Remap] = field(default_factory=list)
    params: list[ParamValue] = field(default_factory=list)
    conditional: bool = False
    #: The conditions every action of this scope runs under (see :func:`guard`).
    guards: tuple[Guard, ...] = ()

    def guarded(self, condition: Condition | None) -> tuple[Guard, ...]:
        """The guards of an action of this scope that has ``condition`` of its own."""
        own = guard(condition)
        return self.guards + ((own,) if own is not None else ())

    def child(self, **changes) -> "Scope":
        return replace(self, configs=dict(self.configs), remaps=list(self.remaps),
                       params=list(self.params), **changes)


def guard(condition: Condition | None) -> Guard | None:
    """``condition`` as a :data:`Guard`: its expression and whether it is negated
    (``UnlessCondition``, ``unless=``). ``None`` for none, or for an expression the analysis
    cannot read: two unknown conditions are never known to be each other's negation."""
    if condition is None or not _readable(condition.expression):
        return None
    return condition.expression, condition.negate


def _readable(expression: Subst) -> bool:
    if isinstance(expression, Unknown):
        return expression.key is not None and _readable(expression.key)
    if isinstance(expression, Join):
        return all(_readable(part) for part in expression.parts)
    if isinstance(expression, Var) and expression.default is not None:
        return _readable(expression.default)
    return True


#: What launch's condition expressions may evaluate to (``launch.conditions.evaluate_condition_expression``).
_TRUTH = {"true": True, "1": True, "false": False, "0": False}


def prefix_namespace(base: str | None, ns: str | None) -> str | None:
    """launch_ros ``prefix_namespace`` followed by ``make_namespace_absolute``.

    Like launch_ros (every distribution since foxy), the result loses its trailing ``/``: a
    node given ``namespace=''`` under ``PushRosNamespace('camera')`` runs in ``/camera``,
    not in the invalid ``/camera/``, and so does one given ``namespace='/camera/'``."""
    if base is not None and ns is not None:
        combined = ns if ns.startswith("/") or not base else ("/" + ns if base == "/" else base + "/" + ns)
    else:
        combined = base if base is not None else ns
    if combined is None:
        return None
    if combined != "/":
        combined = combined.rstrip("/")
    return combined if combined.startswith("/") else "/" + combined


#: ``(package, executable) -> ExecutableRef``, supplied by whoever knows the code graph.
TargetResolver = Callable[[str | None, str | None], ExecutableRef]
#: ``root-relative path -> (actions, problem)``.
FileReader = Callable[[str], "tuple[list[Action], str | None]"]


class Executor:
    def __init__(self, root: Path, packages: PackageIndex, read: FileReader,
                 resolve_target: TargetResolver) -> None:
        self.root = Path(root)
        self.packages = packages
        self.read = read
        self.resolve_target = resolve_target
        self._files_left = MAX_INCLUDED_FILES

    def system(self, path: str) -> System:
        system = System(path)
        scope = Scope(path)
        self._files_left = MAX_INCLUDED_FILES
        self.run_file(path, scope, system, ())
        system.arguments = dict(sorted(scope.configs.items()))
        return system

    def run_file(self, path: str, scope: Scope, system: System, stack: tuple[str, ...]) -> None:
        if path not in system.files:
            system.files.append(path)
        actions, problem = self.read(path)
        if problem:
            system.problems.append(Diagnostic(path, 1, f"launch file not read: {problem}"))
            system.blind = True
        self.declare(actions, scope)
        self.run(actions, scope, system, stack + (path,))

    def declare(self, actions: list[Action], scope: Scope) -> None:
        """Argument defaults first, as the values are looked up when nodes run, after all declarations."""
        for action in actions:
            if isinstance(action, DeclareArgument) and action.name not in scope.configs \
                    and action.default is not None and not scope.opaque:
                scope.configs[action.name] = self.value_or_none(action.default, scope)
            elif isinstance(action, GroupAction):
                self.declare(action.actions, scope)

    # -- substitutions ---------------------------------------------------------------------------
    def setting(self, value: object, scope: Scope) -> object:
        """A parameter's value as the node gets it: XML and YAML launch files keep a value
        with substitutions as written (``$(var depth_topic)``), which launch replaces and
        then types like YAML; ``None`` (unreadable) when they do not resolve here."""
        if not isinstance(value, str) or "$(" not in value:
            return value
        try:
            return scalar(self.value(parse_substitutions(value), scope).strip())
        except Unresolved:
            return None

    def value(self, subst: Subst, scope: Scope) -> str:
        if isinstance(subst, Text):
            return subst.text
        if isinstance(subst, Var):
            if subst.name in scope.configs:
                found = scope.configs[subst.name]
                if found is None:
                    raise Unresolved(f"launch argument '{subst.name}' has no static value")
                return found
            if scope.opaque:
                # The including file may pass it: its value, not this placeholder default.
                raise Unresolved(f"launch argument '{subst.name}' comes from an include "
                                 f"whose arguments are unknown")
            if subst.default is not None:
                return self.value(subst.default, scope)
            raise Unresolved(f"launch argument '{subst.name}' has no default")
        if isinstance(subst, PkgShare):
            package = self.value(subst.package, scope)
            found = self.packages.packages.get(package)
            if found is None:
                raise Unresolved(f"package '{package}' is not in the workspace")
            return found.path
        if isinstance(subst, ThisDir):
            return posixpath.dirname(scope.file) or "."
        if isinstance(subst, Join):
            parts = [self.value(p, scope) for p in subst.parts]
            if subst.sep == "/":
                return posixpath.join(*parts) if parts else ""
            return "".join(parts)
        if isinstance(subst, Unknown):
            raise Unresolved(subst.reason)
        raise Unresolved(f"unsupported substitution {type(subst).__name__}")

    def holds(self, condition: Condition | None, scope: Scope) -> bool | None:
        """Whether an action's ``condition`` holds with the launch arguments the scope has, as
        launch evaluates ``IfCondition``/``UnlessCondition``/``if=``: ``true``/``1`` or
        ``false``/``0`` in any case; ``None`` when the analysis cannot tell."""
        if condition is None:
            return True
        value = self.value_or_none(condition.expression, scope)
        truth = _TRUTH.get(value.lower()) if value is not None else None
        return None if truth is None else truth != condition.negate

    def value_or_none(self, subst: Subst, scope: Scope) -> str | None:
        try:
            return self.value(subst, scope)
        except Unresolved:
            return None

    def locate(self, written: str) -> str | None:
        """A resolved file path as a root-relative path of an existing file, or ``None``."""
        path = posixpath.normpath(written)
        if path.startswith("/") or path.startswith(".."):
            return None
        if (self.root / path).is_file():
            return path
        owners = [p for p in self.packages.packages.values()
                  if p.path == "." or path == p.path or path.startswith(p.path + "/")]
        if not owners:
            return None
        package = max(owners, key=lambda p: len(p.path))
        folder = self.root / package.path
        name = posixpath.basename(path)
        matches = sorted(p for p in folder.rglob(name) if p.is_file()
                         and not any(part in ("build", "install", "log") or part.startswith(".")
                                     for part in p.relative_to(folder).parts[:-1]))
        if len(matches) != 1:
            return None
        return matches[0].relative_to(self.root).as_posix()

    # -- actions ---------------------------------------------------------------------------------
    def run(self, actions: list[Action], scope: Scope, system: System, stack: tuple[str, ...]) -> None:
        for action in actions:
            self.run_one(action, scope, system, stack)

    def run_one(self, action: Action, scope: Scope, system: System, stack: tuple[str, ...]) -> None:
        if isinstance(action, NodeAction):
            system.nodes.append(self.node(action, scope))
        elif isinstance(action, GroupAction):
            inner = scope.child() if action.scoped or action.condition is not None else scope
            if action.condition is not None:
                inner.conditional = True  # (an unscoped conditional group keeps its changes to itself)
                inner.guards = scope.guarded(action.condition)
            self.run(action.actions, inner, system, stack)
        elif isinstance(action, PushNamespace):
            holds = self.holds(action.condition, scope)
            if holds is None:
                # pushed or not: every name the following nodes resolve may be either
                scope.namespace_unknown = "a namespace pushed under a condition the analysis cannot evaluate"
                return
            try:
                if holds:
                    scope.namespace = prefix_namespace(scope.namespace, self.value(action.namespace, scope))
            except Unresolved as exc:
                scope.namespace_unknown = str(exc)
        elif isinstance(action, (SetRemap, SetParameter)) and self.holds(action.condition, scope) is False:
            return
        elif isinstance(action, SetRemap):
            try:
                scope.remaps.append(Remap(self.value(action.source, scope),
                                          self.value(action.target, scope), action.location,
                                          from_scope=True))
            except Unresolved as exc:
                system.problems.append(_problem(action.location, f"SetRemap not followed: {exc}"))
        elif isinstance(action, SetParameter):
            scope.params.append(ParamValue(action.name, self.setting(action.value, scope), action.location,
                                           from_scope=True))
        elif isinstance(action, DeclareArgument):
            if action.name not in scope.configs and action.default is not None and not scope.opaque:
                scope.configs[action.name] = self.value_or_none(action.default, scope)
        elif isinstance(action, SetConfiguration):
            scope.configs[action.name] = self.value_or_none(action.value, scope)
        elif isinstance(action, Include):
            self.include(action, scope, system, stack)
        elif isinstance(action, Unsupported):
            system.problems.append(_problem(
                action.location, f"{action.what} is not followed: nodes it starts are not in the system"))
            if action.starts_nodes:
                system.unfollowed.append(action.location)

    def _handed(self, action: Include, scope: Scope) -> tuple[str | None, ...] | None:
        """The argument values an include the analysis does not follow is handed (``None`` for
        one it cannot read; ``None`` for all when the arguments themselves cannot be read)."""
        if action.arguments is None:
            return None
        return tuple(self.value_or_none(value, scope) for _, value in action.arguments)

    def include(self, action: Include, scope: Scope, system: System, stack: tuple[str, ...]) -> None:
        try:
            written = self.value(action.path, scope)
        except Unresolved as exc:
            system.problems.append(_problem(action.location, f"include not resolved: {exc}"))
            system.unseen_includes.append(self._handed(action, scope))
            return
        path = self.locate(written)
        if path is None:
            system.problems.append(_problem(
                action.location, f"include not resolved: '{written}' is not a file in the workspace"))
            system.unseen_includes.append(self._handed(action, scope))
            return
        if path in stack or len(stack) >= MAX_INCLUDE_DEPTH:
            system.problems.append(_problem(action.location, f"include of '{path}' is recursive"))
            system.blind = True
            return
        if self._files_left <= 0:
            system.problems.append(_problem(
                action.location, f"include of '{path}' not followed: the system already runs "
                                 f"{MAX_INCLUDED_FILES} launch files (include budget)"))
            system.blind = True
            return
        self._files_left -= 1
        inner = scope.child(file=path, conditional=scope.conditional or action.condition is not None,
                            guards=scope.guarded(action.condition))
        if action.arguments is None:
            inner.opaque = True
        else:
            for name, value in action.arguments:
                inner.configs[name] = self.value_or_none(value, scope)
        self.run_file(path, inner, system, stack)

    def node(self, action: NodeAction, scope: Scope) -> LaunchedNode:
        unresolved = list(action.unresolved)

        def get(subst: Subst | None, what: str) -> str | None:
            if subst is None:
                return None
            try:
                return self.value(subst, scope)
            except Unresolved as exc:
                unresolved.append(f"{what}: {exc}")
                return None

        package = get(action.package, "package")
        executable = get(action.executable, "executable")
        name = get(action.name, "name")
        own_ns = get(action.namespace, "namespace")
        if scope.namespace_unknown is not None:
            unresolved.append(f"namespace: {scope.namespace_unknown}")
            namespace = None
        else:
            namespace = prefix_namespace(scope.namespace, own_ns)
        remaps = list(scope.remaps)
        for source, target, location in action.remaps:
            src, dst = get(source, "remap"), get(target, "remap")
            if src is not None and dst is not None:
                remaps.append(Remap(src, dst, location))
        params = list(scope.params) + [ParamValue(n, self.setting(v, scope), loc) for n, v, loc in action.params]
        files: list[ParamFileRef] = []
        for subst, location in action.param_files:
            written = get(subst, "parameters")
            if written is not None:
                files.append(ParamFileRef(self.locate(written), location, written))
        node = LaunchedNode(package, executable, action.location, scope.file, name, namespace,
                            remaps, params, files,
                            conditional=scope.conditional or action.condition is not None,
                            guards=scope.guarded(action.condition),
                            lifecycle=action.lifecycle, unresolved=unresolved)
        node.target = self.resolve_target(package, executable)
        return node


def _problem(location: Location, message: str) -> Diagnostic:
    return Diagnostic(location.path, location.line, message)
