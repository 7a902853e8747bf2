"""Hostile files beyond ``.py`` — launch, YAML, parameter, CMake, manifests — in a workspace with a known bug.

Each case of issue 16 adds one file (or a few) to :mod:`.metadata_workspace`
and runs ``check`` in a subprocess under a tight memory cap and hang guard.
Every case must finish, keep the known ROS201 of the untouched launch file
(one bad file costs only its own precision), and — where the file is
refused — name the file and the limit in a diagnostic.
"""
from __future__ import annotations

import os
from pathlib import Path
from typing import Callable

import pytest

from .metadata_workspace import CHAT, TALKER, check, graph_messages, write_workspace

posix_only = pytest.mark.skipif(os.name != "posix", reason="needs POSIX FIFOs and symlinks")


@pytest.fixture
def ws(tmp_path: Path) -> Path:
    return write_workspace(tmp_path / "ws")


def _write(root: Path, rel: str, content: str | bytes) -> str:
    path = root / rel
    path.parent.mkdir(parents=True, exist_ok=True)
    if isinstance(content, bytes):
        path.write_bytes(content)
    else:
        path.write_text(content, encoding="utf-8")
    return rel


# -- the cases: each adds hostile input and returns (file to be named, message fragment) -------

def yaml_alias_bomb_launch(root: Path) -> tuple[str, str]:
    lines = ["a0: &a0", "  - x", "  - x"]
    for i in range(1, 40):
        lines += [f"a{i}: &a{i}", f"  - *a{i - 1}", f"  - *a{i - 1}"]
    lines += ["launch:", "  - node:", "      pkg: chat_pkg", "      exec: listener", "      param: *a39"]
    return _write(root, f"{CHAT}/launch/bomb.launch.yaml", "\n".join(lines) + "\n"), "aliases are expanded"


def yaml_alias_bomb_parameters(root: Path) -> tuple[str, str]:
    lines = ["a0: &a0 {x: 1, y: 2}"]
    for i in range(1, 40):
        lines += [f"a{i}: &a{i}", f"  p: *a{i - 1}", f"  q: *a{i - 1}"]
    lines += ["listener:", "  ros__parameters:", "    deep: *a39"]
    _write(root, f"{CHAT}/config/listener.yaml", "\n".join(lines) + "\n")
    return "src/chat_pkg/launch/bringup.launch.xml", "aliases are expanded"


def include_fan_out(root: Path) -> tuple[str, str]:
    for i in range(16):
        body = "".join(f'  <include file="$(dirname)/fan{i + 1}.launch.xml"/>\n' for _ in range(8)) \
            if i < 15 else '  <node pkg="chat_pkg" exec="listener"/>\n'
        _write(root, f"{CHAT}/launch/fan{i}.launch.xml", f"<launch>\n{body}</launch>\n")
    return f"{CHAT}/launch/fan14.launch.xml", "include budget"


def unterminated_flow(root: Path) -> tuple[str, str]:
    return _write(root, f"{CHAT}/launch/flow.launch.yaml",
                  "launch:\n  - node: [\n" + "      pkg, exec,\n" * 60_000), "unterminated flow"


def cmake_backtracking(root: Path) -> tuple[str, str | None]:
    _write(root, "src/drive_pkg/CMakeLists.txt",
           "project(drive_pkg)\nadd_executable(driver src/driver.cpp)\ninstall(PROGRAMS" + " " * 5000)
    return "src/drive_pkg/CMakeLists.txt", None


def setup_py_string_bomb(root: Path) -> tuple[str, str | None]:
    lines = ["from setuptools import setup", "s0 = 'xxxxxxxxxxxxxxxx'"]
    lines += [f"s{i} = s{i - 1} + s{i - 1}" for i in range(1, 40)]
    lines += ["setup(name='bomb_pkg', entry_points={'console_scripts': [s39 + ' = bomb_pkg.x:main']})"]
    _write(root, "src/bomb_pkg/package.xml", _package_xml("bomb_pkg"))
    return _write(root, "src/bomb_pkg/setup.py", "\n".join(lines) + "\n"), None


def setup_py_plus_chain(root: Path) -> tuple[str, str | None]:
    chain = " + ".join(["'a'"] * 50_000)
    _write(root, "src/bomb_pkg/package.xml", _package_xml("bomb_pkg"))
    return _write(root, "src/bomb_pkg/setup.py",
                  f"from setuptools import setup\nname = {chain}\nsetup(name='bomb_pkg')\n"), None


def huge_parameter_file(root: Path) -> tuple[str, str]:
    path = root / CHAT / "config" / "listener.yaml"
    with path.open("wb") as handle:
        handle.truncate(200 * 1024 * 1024)  # sparse: costs nothing to create, 200 MB to read
    return "src/chat_pkg/launch/bringup.launch.xml", "limit"


def package_xml_billion_laughs(root: Path) -> tuple[str, str]:
    entities = '<!ENTITY a0 "laugh">' + "".join(
        f'<!ENTITY a{i} "{("&a%d;" % (i - 1)) * 10}">' for i in range(1, 10))
    text = f'<?xml version="1.0"?>\n<!DOCTYPE package [{entities}]>\n<package><name>&a9;</name></package>\n'
    return _write(root, "src/lol_pkg/package.xml", text), "DOCTYPE"


def deep_xml_groups(root: Path) -> tuple[str, str]:
    return _write(root, f"{CHAT}/launch/deep.launch.xml",
                  "<launch>" + "<group>" * 5000 + "</group>" * 5000 + "</launch>\n"), "nested deeper"


def deep_yaml_groups(root: Path) -> tuple[str, str]:
    lines = ["launch:"]
    for depth in range(150):
        pad = "  " * (2 * depth + 1)
        lines += [f"{pad}- group:", f"{pad}    children:"]
    return _write(root, f"{CHAT}/launch/deep.launch.yaml", "\n".join(lines) + "\n"), "nested deeper"


def deep_substitutions(root: Path) -> tuple[str, str]:
    name = "$(var " * 1000 + "x" + ")" * 1000
    return _write(root, f"{CHAT}/launch/subst.launch.xml",
                  f'<launch>\n  <node pkg="chat_pkg" exec="listener" name="{name}"/>\n</launch>\n'), "deeper"


def broken_launch_xml(root: Path) -> tuple[str, str]:
    return _write(root, f"{CHAT}/launch/broken.launch.xml", "<launch>\n  <node pkg='chat_pkg'\n"), "XML error"


def broken_package_xml(root: Path) -> tuple[str, str]:
    return _write(root, "src/half_pkg/package.xml", "<package><name>half_pkg</name>"), "package.xml not read"


def duplicate_package_xml(root: Path) -> tuple[str, str]:
    return _write(root, "src/copy_of_chat/package.xml", _package_xml("chat_pkg")), "also at"


def at_sign_in_launch_path(root: Path) -> tuple[str, str | None]:
    _write(root, f"{CHAT}/launch/robot@2.launch.py", """\
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([Node(package='chat_pkg', executable='listenr')])
""")
    return f"{CHAT}/launch/robot@2.launch.py", None


def non_utf8_file_name(root: Path) -> tuple[str, str | None]:
    (root / os.fsdecode(b"src/chat_pkg/chat_pkg/caf\xe9.py")).write_text(TALKER.replace("'talker'", "'cafe'"))
    return "src/chat_pkg/chat_pkg/talker.py", None


def _package_xml(name: str) -> str:
    from .metadata_workspace import PACKAGE_XML
    return PACKAGE_XML.format(name=name, build_type="ament_python")


CASES: dict[str, Callable[[Path], tuple[str, str | None]]] = {
    f.__name__: f for f in (
        yaml_alias_bomb_launch, yaml_alias_bomb_parameters, include_fan_out, unterminated_flow,
        cmake_backtracking, setup_py_string_bomb, setup_py_plus_chain, huge_parameter_file,
        package_xml_billion_laughs, deep_xml_groups, deep_yaml_groups, deep_substitutions,
        broken_launch_xml, broken_package_xml, duplicate_package_xml, at_sign_in_launch_path,
        non_utf8_file_name,
    )
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_hostile_file_costs_only_itself(ws: Path, case: str) -> None:
    named, fragment = CASES[case](ws)
    checked = check(ws)
    checked.assert_launch_survived()
    if fragment is not None:
        messages = graph_messages(ws)
        assert any(fragment in m for m in messages.get(named, ())), (named, messages)


def test_at_sign_launch_file_is_a_system(ws: Path) -> None:
    at_sign_in_launch_path(ws)
    checked = check(ws)
    assert ("ROS201", f"{CHAT}/launch/robot@2.launch.py", 6) in checked.findings, checked.report


def test_non_utf8_file_name_is_analysed(ws: Path) -> None:
    non_utf8_file_name(ws)
    checked = check(ws)
    checked.assert_launch_survived()
    assert not any("internal error" in d["message"] for d in checked.report["diagnostics"])


def test_cmake_executables_still_read(ws: Path) -> None:
    """The linear CMake reader keeps reading targets: a launch typo of a CMake target is found."""
    _write(ws, f"{CHAT}/launch/drive.launch.xml", '<launch>\n  <node pkg="drive_pkg" exec="drivr"/>\n'
                                                  '  <node pkg="drive_pkg" exec="driver"/>\n</launch>\n')
    checked = check(ws)
    assert ("ROS201", f"{CHAT}/launch/drive.launch.xml", 2) in checked.findings
    assert ("ROS201", f"{CHAT}/launch/drive.launch.xml", 3) not in checked.findings


# -- special files: FIFOs, devices, links out of the workspace ------------------------------------

@posix_only
@pytest.mark.parametrize("name", ["src/fifo_pkg/package.xml", f"{CHAT}/launch/pipe.launch.xml",
                                  f"{CHAT}/launch/pipe.launch.yaml", f"{CHAT}/config/listener.yaml",
                                  "src/drive_pkg/CMakeLists.txt", f"{CHAT}/setup.cfg"])
def test_fifo_never_blocks(ws: Path, name: str) -> None:
    path = ws / name
    path.parent.mkdir(parents=True, exist_ok=True)
    if path.exists():
        path.unlink()
    os.mkfifo(path)
    check(ws, allowed=(0, 1))  # an unreadable setup.cfg makes chat_pkg's executables unknown: quiet
    shown = name if not name.endswith("listener.yaml") else f"{CHAT}/launch/bringup.launch.xml"
    messages = graph_messages(ws)
    assert any("not a regular file" in m or "is not a file" in m for m in messages.get(shown, ())), messages


@posix_only
def test_launch_yaml_linked_to_dev_zero(ws: Path) -> None:
    if not Path("/dev/zero").exists():
        pytest.skip("no /dev/zero")
    (ws / CHAT / "launch" / "zero.launch.yaml").symlink_to("/dev/zero")
    checked = check(ws)
    checked.assert_launch_survived()
    assert any("outside the workspace" in m for m in checked.diagnostics_on(f"{CHAT}/launch/zero.launch.yaml"))


@posix_only
def test_python_file_linked_outside_is_not_read(ws: Path, tmp_path: Path) -> None:
    outside = tmp_path / "elsewhere.py"
    outside.write_text(TALKER.replace("'talker'", "'outsider'"))
    (ws / CHAT / "chat_pkg" / "linked.py").symlink_to(outside)
    done = check(ws).done
    assert "outsider" not in done.stdout
    graph_done = __import__("subprocess").run(
        [__import__("sys").executable, "-m", "flake8_rosgraph", "graph", str(ws)],
        capture_output=True, text=True, timeout=60)
    assert "/outsider" not in graph_done.stdout
    assert "src/chat_pkg/chat_pkg/linked.py:1: warning: skipped: a link to a file outside the workspace" \
        in graph_done.stderr


@posix_only
def test_parameter_file_linked_to_a_secret_does_not_leak(ws: Path, tmp_path: Path) -> None:
    secret = tmp_path / "credentials"
    secret.write_text("AWS_SECRET=wJalrXUtnFEMI/K7MDENG/bPxRfiCYEXAMPLEKEY\n")
    params = ws / CHAT / "config" / "listener.yaml"
    params.unlink()
    params.symlink_to(secret)
    checked = check(ws)
    checked.assert_launch_survived()
    graph_done = __import__("subprocess").run(
        [__import__("sys").executable, "-m", "flake8_rosgraph", "graph", str(ws)],
        capture_output=True, text=True, timeout=60)
    for output in (checked.done.stdout, checked.done.stderr, graph_done.stdout, graph_done.stderr):
        assert "wJalrXUtnFEMI" not in output and "AWS_SECRET" not in output
    assert "outside the workspace" in graph_done.stdout


# -- the did-you-mean index --------------------------------------------------------------------

def test_many_long_topic_names_stay_cheap(ws: Path) -> None:
    long = "/".join(["very_long_namespace_segment"] * 7)  # about 200 characters: valid, but long
    # each subscription a transposition typo of its publisher: every one has a near miss to find
    pubs = "".join(f"        self.create_publisher(String, '/{long}/status{i}', 10)\n" for i in range(200))
    subs = "".join(f"        self.create_subscription(String, '/{long}/statsu{i}', self.cb, 10)\n" for i in range(200))
    _write(ws, f"{CHAT}/chat_pkg/wide.py", f"""\
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Wide(Node):
    def __init__(self):
        super().__init__('wide')
{pubs}

class Narrow(Node):
    def __init__(self):
        super().__init__('narrow')
{subs}
    def cb(self, msg):
        pass


def main():
    rclpy.init()
    rclpy.spin(Wide())
""")
    checked = check(ws)
    checked.assert_launch_survived()
    assert sum(1 for f in checked.report["findings"] if f["code"] == "ROS003") == 200


# -- folders that cannot be listed ---------------------------------------------------------------

@pytest.mark.parametrize("folder", [f"{CHAT}/config", f"{CHAT}/launch", "src/drive_pkg"])
def test_unlistable_folder_is_a_diagnostic(ws: Path, folder: str, monkeypatch: pytest.MonkeyPatch) -> None:
    """A folder that cannot be listed (no permission; simulated, since tests may run as root) is named,
    and costs only what is inside it."""
    from flake8_rosgraph.analysis import build_graph

    _write(ws, f"{CHAT}/launch/other.launch.xml", '<launch>\n  <node pkg="chat_pkg" exec="lisener"/>\n</launch>\n')
    blocked = os.path.abspath(ws / folder)
    real_scandir = os.scandir

    def scandir(path=".", *args, **kwargs):
        if os.path.abspath(os.fspath(path)) == blocked:
            raise PermissionError(13, "Permission denied", os.fspath(path))
        return real_scandir(path, *args, **kwargs)

    monkeypatch.setattr(os, "scandir", scandir)
    graph = build_graph(ws)
    named = [d for d in graph.diagnostics if d.path == folder]
    assert any("folder not read" in d.message and "Permission denied" in d.message for d in named), \
        graph.diagnostics
    files = {s.launch_file for s in graph.systems}
    if folder.endswith("launch"):
        assert not files
    else:
        assert {f"{CHAT}/launch/bringup.launch.xml", f"{CHAT}/launch/other.launch.xml"} <= files
        assert not any("internal error" in d.message for d in graph.diagnostics)


@posix_only
def test_flake8_on_one_file_beside_a_fifo_manifest(ws: Path) -> None:
    """The FIFO is in another package; flake8 checks one unrelated file and must not block on it."""
    from .harness import flake8_executable, run
    from .metadata_workspace import TIGHT_GUARD_S, TIGHT_MEMORY

    (ws / "src" / "fifo_pkg").mkdir()
    os.mkfifo(ws / "src" / "fifo_pkg" / "package.xml")
    os.mkfifo(ws / CHAT / "launch" / "pipe.launch.xml")
    done = run([flake8_executable(), "--isolated", "--select", "ROS", str(ws / CHAT / "chat_pkg" / "talker.py")],
               ws, memory_cap=TIGHT_MEMORY, hang_guard=TIGHT_GUARD_S)
    assert done is not None and done.returncode == 0 and "Traceback" not in done.stderr, done and done.explain()
