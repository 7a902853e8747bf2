"""The catalogue: shipped standard definitions, workspace and user interface folders, class names."""
import os

import pytest

from flake8_rosgraph.interfaces.catalogue import (MAX_INTERFACE_BYTES, display_name, load_catalogue,
                                                  message_key, standard_catalogue)

#: The packages issue 11 asks to ship.
REQUIRED = ("std_msgs", "builtin_interfaces", "geometry_msgs", "sensor_msgs", "nav_msgs", "std_srvs",
            "example_interfaces", "action_msgs", "rcl_interfaces", "diagnostic_msgs",
            "visualization_msgs", "trajectory_msgs", "tf2_msgs", "shape_msgs", "lifecycle_msgs",
            "unique_identifier_msgs", "action_tutorials_interfaces")


@pytest.mark.parametrize("qualname, key", [
    ("std_msgs.msg.String", "std_msgs/msg/String"),
    ("std_msgs.msg._string.String", "std_msgs/msg/String"),
    ("std_srvs.srv.SetBool.Response", "std_srvs/srv/SetBool_Response"),
    ("std_srvs.srv.SetBool_Request", "std_srvs/srv/SetBool_Request"),
    ("nav2_msgs.action.NavigateToPose.Goal", "nav2_msgs/action/NavigateToPose_Goal"),
    ("std_srvs.srv.SetBool", None),
    ("std_msgs.msg.String.Request", None),
    ("std_srvs.srv.SetBool.Goal", None),
    ("rclpy.time.Time", None),
    ("msg.String", None),
])
def test_message_key(qualname, key):
    assert message_key(qualname) == key


def test_display_name():
    assert display_name("std_srvs/srv/SetBool_Response") == "std_srvs/srv/SetBool.Response"
    assert display_name("std_msgs/msg/String") == "std_msgs/msg/String"


def test_standard_packages_are_shipped():
    catalogue = standard_catalogue()
    packages = {key.split("/", 1)[0] for key in catalogue.messages}
    assert set(REQUIRED) <= packages
    header = catalogue.get("std_msgs/msg/Header")
    assert [(f.name, f.type.base) for f in header.fields] == [
        ("stamp", "builtin_interfaces/msg/Time"), ("frame_id", "string")]
    scan = catalogue.get("sensor_msgs/msg/LaserScan").field("ranges")
    assert (scan.type.base, scan.type.array) == ("float32", "unbounded")
    assert "STATUS_FIX" in catalogue.get("sensor_msgs/msg/NavSatStatus").constants
    assert catalogue.get("action_tutorials_interfaces/action/Fibonacci_Goal").field("order")


def _package(folder, name, files):
    folder.mkdir(parents=True)
    (folder / "package.xml").write_text(f"<package format='3'><name>{name}</name></package>")
    for rel, text in files.items():
        path = folder / rel
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)


def test_workspace_packages_override_shipped_and_user_folders(tmp_path):
    ws, extra = tmp_path / "ws", tmp_path / "vendor"
    _package(ws / "src" / "robot_msgs", "robot_msgs", {
        "msg/Wheel.msg": "float64 speed\nState state\n",
        "msg/State.msg": "uint8 mode\n",
        "srv/Reset.srv": "---\nbool ok\n",
        "msg/notes.txt": "not an interface\n",
        "msg/Broken.msg": "int32 9\n",
    })
    _package(extra / "vendor_msgs", "vendor_msgs", {"action/Dock.action": "string id\n---\n---\nfloat32 left\n"})
    _package(ws / "src" / "ignored", "ignored_msgs", {"msg/X.msg": "int8 x\n", "COLCON_IGNORE": ""})
    catalogue = load_catalogue(ws, [extra])
    assert catalogue.get("robot_msgs/msg/Wheel").field("state").type.base == "robot_msgs/msg/State"
    assert catalogue.get("robot_msgs/srv/Reset_Response").field("ok")
    assert catalogue.get("vendor_msgs/action/Dock_Feedback").field("left")
    assert catalogue.get("ignored_msgs/msg/X") is None
    assert catalogue.get("std_msgs/msg/String") is not None
    assert catalogue.problems == [("src/robot_msgs/msg/Broken.msg",
                                   "interface file not read: robot_msgs/msg/Broken line 1: "
                                   "bad field name '9'")]


def test_oversized_and_special_files_cost_only_themselves(tmp_path):
    _package(tmp_path / "big_msgs", "big_msgs", {
        "msg/Big.msg": "int8 x\n" * (MAX_INTERFACE_BYTES // 7 + 1),
        "msg/Small.msg": "int8 x\n",
    })
    if hasattr(os, "mkfifo"):
        os.mkfifo(tmp_path / "big_msgs" / "msg" / "Pipe.msg")
    catalogue = load_catalogue(tmp_path)
    assert catalogue.get("big_msgs/msg/Small") is not None
    assert catalogue.get("big_msgs/msg/Big") is None
    assert all("not read" in why for _, why in catalogue.problems)
    assert {path for path, _ in catalogue.problems} >= {"big_msgs/msg/Big.msg"}


def test_links_are_not_followed_out_of_the_tree(tmp_path):
    outside = tmp_path / "outside"
    _package(outside / "secret_msgs", "secret_msgs", {"msg/Secret.msg": "int8 x\n"})
    ws = tmp_path / "ws"
    ws.mkdir()
    (ws / "link").symlink_to(outside / "secret_msgs", target_is_directory=True)
    _package(ws / "real_msgs", "real_msgs", {"msg/Real.msg": "int8 x\n"})
    (ws / "real_msgs" / "msg" / "Linked.msg").symlink_to(outside / "secret_msgs" / "msg" / "Secret.msg")
    catalogue = load_catalogue(ws)
    assert catalogue.get("secret_msgs/msg/Secret") is None
    assert catalogue.get("real_msgs/msg/Linked") is None
    assert catalogue.get("real_msgs/msg/Real") is not None
