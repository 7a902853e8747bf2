"""Names whose other end lives outside any Python workspace, so an absence there proves nothing.

The "without" rules (ROS001, ROS003, ROS008, ROS009) and the self-loop rule
(ROS002) skip these names. Each built-in entry says why it is there; users add
their own through :attr:`RuleConfig.external_names` (the
``--rosgraph-external-topics`` option), with the same pattern syntax:

* an entry without wildcards is an exact name; a missing leading ``/`` is added
  (``cmd_vel`` means ``/cmd_vel``), because graph names are fully resolved;
* ``*`` matches within one name component, ``?`` one character of a component,
  ``**`` any run of characters including ``/`` (so ``/**/get_parameters``
  matches ``/a/get_parameters`` and ``/ns/a/get_parameters``).
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Iterable

#: (pattern, why it is exempt, the one message type it carries or None). Exact names first, then
#: per-node built-in endpoints. The typed ones are infrastructure topics whose slips of the pen
#: :mod:`.infrastructure` recognises.
_EXEMPT: tuple[tuple[str, str, str | None], ...] = (
    ("/rosout", "every node publishes its log here; rcl logging, rqt_console and bags consume it", None),
    ("/parameter_events", "every node publishes parameter changes here; `ros2 param` and parameter "
                          "event handlers consume it", None),
    ("/tf", "the transform tree: broadcast and buffered by tf2 in C++ nodes, rviz and "
            "robot_state_publisher", "tf2_msgs/msg/TFMessage"),
    ("/tf_static", "static transforms, usually from robot_state_publisher or static_transform_publisher",
     "tf2_msgs/msg/TFMessage"),
    ("/clock", "published by simulators and `ros2 bag play --clock`; every node with use_sim_time "
               "subscribes", "rosgraph_msgs/msg/Clock"),
    ("/diagnostics", "aggregated by diagnostic_aggregator and shown by rqt_robot_monitor, both C++ tools",
     "diagnostic_msgs/msg/DiagnosticArray"),
    ("/diagnostics_agg", "published by diagnostic_aggregator's aggregator_node (C++) from `/diagnostics`; "
                         "rqt_robot_monitor and robot dashboards consume it", "diagnostic_msgs/msg/DiagnosticArray"),
    ("/diagnostics_toplevel_state", "published by diagnostic_aggregator's aggregator_node (C++): the "
                                    "worst level of all analyzers", "diagnostic_msgs/msg/DiagnosticStatus"),
    ("/robot_description", "published (latched) by robot_state_publisher from the URDF",
     "std_msgs/msg/String"),
    ("/joint_states", "joint_state_publisher or ros2_control's joint_state_broadcaster publish it, "
                      "robot_state_publisher consumes it; Python code is usually one half of that pair",
     "sensor_msgs/msg/JointState"),
    ("/initialpose", "published by rviz2's '2D Pose Estimate' tool",
     "geometry_msgs/msg/PoseWithCovarianceStamped"),
    ("/goal_pose", "published by rviz2's '2D Goal Pose' tool", "geometry_msgs/msg/PoseStamped"),
    ("/clicked_point", "published by rviz2's 'Publish Point' tool", "geometry_msgs/msg/PointStamped"),
    ("/**/describe_parameters", "parameter service every node serves (rclpy, rclcpp)", None),
    ("/**/get_parameter_types", "parameter service every node serves (rclpy, rclcpp)", None),
    ("/**/get_parameters", "parameter service every node serves (rclpy, rclcpp)", None),
    ("/**/list_parameters", "parameter service every node serves (rclpy, rclcpp)", None),
    ("/**/set_parameters", "parameter service every node serves (rclpy, rclcpp)", None),
    ("/**/set_parameters_atomically", "parameter service every node serves (rclpy, rclcpp)", None),
    ("/**/get_type_description", "type description service every node serves (Jazzy and later)", None),
    ("/**/get_logger_levels", "logger service a node serves when started with the logger service enabled", None),
    ("/**/set_logger_levels", "logger service a node serves when started with the logger service enabled", None),
    ("/**/change_state", "lifecycle service every lifecycle node serves (also C++ ones)", None),
    ("/**/get_state", "lifecycle service every lifecycle node serves (also C++ ones)", None),
    ("/**/get_available_states", "lifecycle service every lifecycle node serves (also C++ ones)", None),
    ("/**/get_available_transitions", "lifecycle service every lifecycle node serves (also C++ ones)", None),
    ("/**/get_transition_graph", "lifecycle service every lifecycle node serves (also C++ ones)", None),
    ("/**/transition_event", "lifecycle topic every lifecycle node publishes (also C++ ones)", None),
)
#: Message packages made for tools outside any workspace, and the tool: an end of such a type
#: with no partner here meets that tool (rviz draws markers and serves interactive markers'
#: feedback), so it is taken for an interface — a slip of its name is still reported.
TOOL_MESSAGE_PACKAGES: dict[str, str] = {
    "visualization_msgs": "rviz (and Foxglove) display markers and interactive markers and send their feedback",
}


def for_a_tool(message_type: str | None) -> bool:
    """Whether ``message_type`` (``pkg/msg/Name``) belongs to a package of :data:`TOOL_MESSAGE_PACKAGES`."""
    return message_type is not None and message_type.split("/", 1)[0] in TOOL_MESSAGE_PACKAGES


#: (pattern, why it is exempt), for the docs and the lookups.
BUILTIN_EXEMPT: tuple[tuple[str, str], ...] = tuple((pattern, why) for pattern, why, _ in _EXEMPT)
#: Infrastructure topics and the one type each carries.
INFRASTRUCTURE_TYPES: dict[str, str] = {pattern: kind for pattern, _, kind in _EXEMPT if kind is not None}

_WILDCARDS = re.compile(r"\*\*|\*|\?")
_WILDCARD_REGEX = {"**": ".*", "*": "[^/]*", "?": "[^/]"}


def _normalize(entry: str) -> str:
    entry = entry.strip()
    return entry if entry.startswith("/") else "/" + entry


def _compile(pattern: str) -> re.Pattern[str]:
    parts: list[str] = []
    pos = 0
    for match in _WILDCARDS.finditer(pattern):
        parts.append(re.escape(pattern[pos:match.start()]))
        parts.append(_WILDCARD_REGEX[match.group()])
        pos = match.end()
    parts.append(re.escape(pattern[pos:]))
    return re.compile("".join(parts))


@dataclass(frozen=True)
class ExemptNames:
    """The built-in exempt list plus the user's external names, ready for fast lookups."""

    exact: frozenset[str]
    patterns: tuple[re.Pattern[str], ...]

    @classmethod
    def build(cls, external: Iterable[str] = ()) -> ExemptNames:
        entries = [p for p, _ in BUILTIN_EXEMPT] + [_normalize(e) for e in external if e.strip()]
        exact = frozenset(e for e in entries if not _WILDCARDS.search(e))
        patterns = tuple(_compile(e) for e in sorted(set(entries) - exact))
        return cls(exact, patterns)

    def __contains__(self, name: object) -> bool:
        if not isinstance(name, str):
            return False
        return name in self.exact or any(p.fullmatch(name) for p in self.patterns)
