"""Fields of the standard messages that ROS 2 renamed from ROS 1.

rosidl allows lower-case field names only, so the few ROS 1 fields written in capitals were
renamed when common_msgs moved to ROS 2 (``sensor_msgs/CameraInfo``'s ``D``, ``K``, ``R`` and
``P`` became ``d``, ``k``, ``r`` and ``p``). Code ported from ROS 1 keeps the old name and
raises ``AttributeError``; code written for both versions uses each on its own branch.
"""
from __future__ import annotations

#: Definition key → {ROS 1 field name: ROS 2 field name}.
RENAMED_FROM_ROS1: dict[str, dict[str, str]] = {
    "sensor_msgs/msg/CameraInfo": {"D": "d", "K": "k", "R": "r", "P": "p"},
}


def ros2_name(message: str, field: str) -> str | None:
    """The ROS 2 name of ``message``'s ROS 1 field ``field`` (definition keys), else ``None``."""
    return RENAMED_FROM_ROS1.get(message, {}).get(field)
