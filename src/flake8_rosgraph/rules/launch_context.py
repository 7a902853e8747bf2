"""What the launch files of the workspace say about a node written in code, for the rules that
judge names by the namespace a node runs in.

A launch file whose executable the analysis cannot tie to code (a name built from a
launch argument, or an entry point it could not follow) may start any node of its
package: when it does so in a namespace, a node of that package is not known to run
at the root.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Any, Iterator

from ..graph import names
from ..graph.model import Entity, RosGraph, RosNode
from ..launch.model import LaunchedNode, System

#: Launch targets not tied to code: the node they start may be any of the package's.
_UNMATCHED = ("unknown", "missing-executable")


def packages_maybe_namespaced(graph: RosGraph) -> frozenset[str]:
    """Packages a launch file starts an executable of, not tied to code, in a namespace."""
    return frozenset(
        launched.package for system in graph.systems for launched in system.nodes
        if launched.package and _unmatched(launched.target)
        and (launched.is_unresolved("namespace") or (launched.namespace or "/").strip("/")))


def _unmatched(target) -> bool:
    return target.status in _UNMATCHED or (target.status == "no-python" and target.entry is not None)


def in_package(node: RosNode, packages: frozenset[str]) -> bool:
    """Whether the node's code lies in a folder named like one of ``packages``."""
    return bool(packages) and not packages.isdisjoint(node.location.path.split("/")[:-1])


def launched_in_namespace(node: RosNode) -> bool:
    """Whether a launch file starts this node copy in a namespace other than the root."""
    return node.launch is not None and bool((node.namespace or "/").strip("/"))


def unseen_remap_targets(graph: RosGraph) -> frozenset[str]:
    """The names a launch file remaps a node of unseen code onto (an installed package's
    executable, a C++ one whose names the analysis reads in part): the launch file says that
    node uses the name, in a role the analysis cannot see, so it may be the missing other end.

    A relative target lands in the node's namespace; a private one (``~/x``) or one under an
    unknown namespace is left out: its full name is not known.
    """
    out: set[str] = set()
    for _, launched in _unseen_launched(graph):
        for remap in launched.remaps:
            name = _landing(remap.target, launched.namespace)
            if name is not None:
                out.add(name)
    return frozenset(out)


def _unseen_launched(graph: RosGraph) -> Iterator[tuple[System, LaunchedNode]]:
    """Every launched node whose code the analysis does not see (an installed package's
    executable, a C++ one read in part), with its system."""
    for system in graph.systems:
        analysed = {id(instance.launched) for instance in system.instances if instance.analysed}
        yield from ((system, launched) for launched in system.nodes if id(launched) not in analysed)


def _landing(target: str, namespace: str | None) -> str | None:
    """Where a remap target lands for a node in ``namespace`` (``None``: not known statically)."""
    if not target or target.startswith("~") or "$" in target or "{" in target:
        return None
    if target.startswith("/"):
        return target
    if namespace is None:
        return None
    return namespace.rstrip("/") + "/" + target


#: A ros2_control controller's ``type``: ``package/Class`` (``joint_trajectory_controller/JointTrajectoryController``).
_PLUGIN_TYPE = re.compile(r"[A-Za-z_]\w*/[A-Za-z_]\w*")


def _unseen_settings(graph: RosGraph) -> Iterator[tuple[LaunchedNode, str, Any]]:
    """``(launched node, parameter, value)`` for every value a launch file hands a node whose
    code the analysis does not see (an installed package's executable, a C++ one read in part):
    inline, and in the sections of its parameter files that may be meant for it (every section
    when its name is not known)."""
    for system, launched in _unseen_launched(graph):
        for param in launched.params:
            yield launched, param.name, param.value
        fqn = None if launched.name is None or launched.unresolved \
            else names.fqn(launched.name, launched.namespace or "/")
        for file in launched.param_files:
            for section in system.parameter_files.get(file.path or "", []):
                if fqn is None or section.matches(fqn):
                    for name, value, _ in section.settings:
                        yield launched, name, value


def controller_namespaces(graph: RosGraph) -> frozenset[str]:
    """Where the ros2_control controllers the workspace configures have their names.

    A controller manager (``ros2_control_node``, installed) given ``<controller>.type:
    package/Class`` loads that controller as a node ``<controller>`` in its own namespace, and
    the controller's topics, services and actions (``/arm_controller/joint_trajectory``,
    ``/franka_robot_state_broadcaster/robot_state``) live under that node: a C++ plugin outside
    the workspace is their other end. Only names under a configured controller's name count:
    a name the workspace uses elsewhere is judged as before.
    """
    out: set[str] = set()
    for launched, name, value in _unseen_settings(graph):
        controller, _, key = name.rpartition(".")
        if key != "type" or not controller or "." in controller or not isinstance(value, str) \
                or not _PLUGIN_TYPE.fullmatch(value) or launched.is_unresolved("namespace"):
            continue
        if names.validate_node_name(controller).ok:
            out.add((launched.namespace or "/").rstrip("/") + "/" + controller)
    return frozenset(out)


def unseen_parameter_names(graph: RosGraph) -> frozenset[str]:
    """Absolute names a launch file hands as parameter values to a node whose code the analysis
    does not see (robot_localization's ``imu1: /mag/heading_imu``, a bridge's ``ros_topic_name``):
    that program names its ends by its parameters, so it may be the missing other end of
    exactly that name. Relative values are left out: frame ids (``odom``, ``base_link``) are
    relative too."""
    return frozenset(value for _, _, value in _unseen_settings(graph)
                     if isinstance(value, str) and value.startswith("/") and len(value) > 1
                     and names.validate_full_topic_name(value).ok)


def unseen_code_names(graph: RosGraph) -> frozenset[str]:
    """The names nodes hand, with themselves, to a library the analysis cannot see into
    (:attr:`~flake8_rosgraph.graph.model.RosNode.unseen_names`), expanded where each node
    runs: in code as written, and as each launch file starts it."""
    out: set[str] = set()
    placed = [(node, node, []) for node in graph.nodes if node.launch is None]
    placed += [(instance.node, instance.code,
                [names.RemapRule(r.source, r.target) for r in instance.launched.remaps])
               for system in graph.systems for instance in system.instances]
    for node, code, rules in placed:
        if node.name is None or node.namespace is None:
            continue
        for raw in code.unseen_names:
            expanded, _ = names.expand_topic_name(raw, node.name, node.namespace)
            if expanded is None:
                continue
            out.add(expanded)
            rule = names.first_remap_match(expanded, rules, node.name, node.namespace)
            if rule is not None:  # the launch file moves the library's end too
                remapped, _ = names.expand_topic_name(rule.replacement, node.name, node.namespace)
                if remapped is not None:
                    out.add(remapped)
    return frozenset(out)


@dataclass(frozen=True)
class UnseenLaunches:
    """Where launch files may start a package's nodes renamed in ways the analysis cannot see.

    ``folders``: the package folders (``kalman_slam/``) of launch files that run actions the
    analysis cannot follow and that may start nodes (an ``OpaqueFunction`` building its nodes
    from configuration) — a launch file starts its own package's nodes. ``packages``: packages a
    launch file starts an executable of, not tied to code, with remaps or a namespace (or with
    remaps or a namespace the analysis cannot read): that may be any node of the package.
    """

    folders: frozenset[str]
    packages: frozenset[str]

    @classmethod
    def of(cls, graph: RosGraph) -> "UnseenLaunches":
        folders = {_package_folder(location.path) for system in graph.systems for location in system.unfollowed}
        packages = {launched.package for system in graph.systems for launched in system.nodes
                    if launched.package and _unmatched(launched.target) and _renames(launched)}
        return cls(frozenset(folders), frozenset(packages))

    def may_rename(self, node: RosNode) -> bool:
        """Whether ``node``, judged as written in code, may be started renamed by such a launch file."""
        return node.launch is None and (
            any(folder and node.location.path.startswith(folder) for folder in self.folders)
            or in_package(node, self.packages))


def _renames(launched: LaunchedNode) -> bool:
    return bool(launched.remaps) or launched.is_unresolved("remappings") \
        or launched.is_unresolved("namespace") or bool((launched.namespace or "/").strip("/"))


def _package_folder(launch_path: str) -> str:
    """``pkg/`` for ``pkg/launch/x.launch.py`` (the folder above ``launch/``), else the file's folder."""
    parts = launch_path.split("/")[:-1]
    if "launch" in parts:
        parts = parts[:len(parts) - 1 - parts[::-1].index("launch")]
    return "/".join(parts) + "/" if parts else ""


#: Message types of the topics a transport plugin adds one token under the base topic of a
#: program's image or point cloud (image_transport's ``/camera/image_raw/compressed``,
#: ``/theora``, ``/ffmpeg``; point_cloud_transport's ``/draco``, ``/zstd``).
TRANSPORT_TYPES = frozenset({
    "sensor_msgs/msg/CompressedImage",
    "theora_image_transport/msg/Packet",
    "ffmpeg_image_transport_msgs/msg/FFMPEGPacket",
    "point_cloud_interfaces/msg/CompressedPointCloud2",
})


def transported(entity: Entity, targets: frozenset[str]) -> bool:
    """Whether ``entity`` is one of the names a launch file remaps a node of unseen code onto
    (:func:`unseen_remap_targets`), or a transport plugin's topic one token under one of them
    (its type a transport's, or unknown). Other names under a target are not that program's:
    a remap onto ``/odom`` says nothing of ``/odom/wheels``."""
    name = entity.name
    if name is None:
        return False
    return name in targets or (name.rsplit("/", 1)[0] in targets
                               and (entity.type is None or entity.type in TRANSPORT_TYPES))


def under_any(name: str | None, roots: frozenset[str]) -> bool:
    """Whether ``name`` is one of ``roots`` or lies under one (a library handed ``image_raw``
    may derive ``image_raw/compressed``)."""
    if name is None:
        return False
    return name in roots or any(name.startswith(root.rstrip("/") + "/") for root in roots)
