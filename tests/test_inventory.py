"""One listing of the workspace per run, shared by every reader (:mod:`flake8_rosgraph.inventory`)."""
from __future__ import annotations

import os
from pathlib import Path

from flake8_rosgraph import inventory, metadata, workspace
from flake8_rosgraph.cache import workspace_inputs
from flake8_rosgraph.cpp.sources import cpp_sources

from test_workspace_discovery import PACKAGE_XML

TALKER = """import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Talker(Node):
    def __init__(self):
        super().__init__('talker')
        self.pub = self.create_publisher(String, 'chatter', 10)
"""


def _workspace(tmp_path: Path) -> Path:
    root = tmp_path / "ws"
    src = root / "src"
    for name, build in (("talker_py", "ament_python"), ("legacy_nav", "catkin")):
        pkg = src / name
        (pkg / name).mkdir(parents=True)
        (pkg / "package.xml").write_text(PACKAGE_XML.format(name=name, build=build))
        (pkg / name / "__init__.py").write_text("")
        (pkg / name / "talker.py").write_text(TALKER)
        (pkg / "launch").mkdir()
        (pkg / "launch" / "talk.launch.xml").write_text('<launch><node pkg="talker_py" exec="talker"/></launch>\n')
    driver = src / "driver_cpp"
    (driver / "src").mkdir(parents=True)
    (driver / "package.xml").write_text(PACKAGE_XML.format(name="driver_cpp", build="ament_cmake"))
    (driver / "src" / "driver.cpp").write_text('#include "rclcpp/rclcpp.hpp"\n')
    (src / "ignored").mkdir()
    (src / "ignored" / "COLCON_IGNORE").write_text("")
    (src / "ignored" / "old.py").write_text("import rclpy\n")
    (tmp_path / "outside").mkdir()
    (tmp_path / "outside" / "linked.py").write_text("import rclpy\n")
    (src / "link_to_outside").symlink_to(tmp_path / "outside", target_is_directory=True)
    return root


def _walk(top, shared: bool, onerror=None):
    seen = []
    if shared:
        with inventory.shared(top):
            walker = inventory.walk(top, onerror)
            for dirpath, dirnames, filenames in walker:
                dirnames[:] = sorted(d for d in dirnames if d != "launch")
                seen.append((dirpath, sorted(dirnames), sorted(filenames)))
        return seen
    for dirpath, dirnames, filenames in os.walk(top, followlinks=False, onerror=onerror):
        dirnames[:] = sorted(d for d in dirnames if d != "launch")
        seen.append((dirpath, sorted(dirnames), sorted(filenames)))
    return seen


def test_a_shared_walk_is_os_walk_with_links_listed_not_entered_and_pruning_honoured(tmp_path):
    root = _workspace(tmp_path)
    for top in (root, root / "src", Path(os.path.relpath(root / "src"))):
        assert _walk(top, shared=True) == _walk(top, shared=False)
    listed = {d for _, dirnames, _ in _walk(root, shared=True) for d in dirnames}
    entered = {Path(p).name for p, _, _ in _walk(root, shared=True)}
    assert "link_to_outside" in listed and "link_to_outside" not in entered
    assert "launch" not in entered  # pruned by the walker, as with os.walk


def test_a_folder_that_cannot_be_listed_reaches_every_walkers_onerror(tmp_path, monkeypatch):
    root = _workspace(tmp_path)
    locked = str(root / "src" / "driver_cpp" / "src")
    scandir = os.scandir

    def refusing(path="."):
        if os.fspath(path) == locked:
            raise PermissionError(13, "Permission denied", locked)
        return scandir(path)

    monkeypatch.setattr(os, "scandir", refusing)  # os.walk lists through it too
    plain: list[OSError] = []
    assert _walk(root, shared=True) == _walk(root, shared=False, onerror=plain.append)
    errors: list[OSError] = []
    with inventory.shared(root):
        for _ in range(2):
            list(inventory.walk(root, errors.append))
    assert [e.filename for e in errors] == [e.filename for e in plain] * 2 == [locked] * 2


def test_every_reader_of_one_run_sees_the_same_tree(tmp_path):
    root = _workspace(tmp_path)
    late = root / "src" / "talker_py" / "talker_py" / "late.py"
    with inventory.shared(root):
        before = workspace.python_files(root)
        late.write_text(TALKER)  # written while the run walks: in no reader's view of this run
        assert workspace.python_files(root) == before
        assert all(rel != "src/talker_py/talker_py/late.py" for rel, _ in workspace_inputs(root))
    assert late in workspace.python_files(root)  # the next run lists the folder again


def test_readers_agree_with_and_without_the_shared_listing(tmp_path):
    root = _workspace(tmp_path)

    def readings():
        meta = metadata.read_metadata(root)
        return (meta.python_files, meta.launch_files, sorted(meta.packages.packages),
                sorted(map(repr, meta.diagnostics)), cpp_sources(root), workspace_inputs(root))

    plain = readings()
    with inventory.shared(root):
        assert readings() == plain
    python_files, launch_files, packages, diagnostics, _, _ = plain
    assert python_files == ["src/talker_py/talker_py/__init__.py", "src/talker_py/talker_py/talker.py"]
    assert launch_files == ["src/talker_py/launch/talk.launch.xml"]
    assert any("ROS 1 (catkin) package 'legacy_nav'" in d for d in diagnostics)
    assert any("COLCON_IGNORE" in d for d in diagnostics)


def test_each_manifest_is_asked_about_ros1_once_a_run(tmp_path, monkeypatch):
    root = _workspace(tmp_path)
    reads: list[str] = []
    small_text = workspace._small_text

    def counting(path, limit):
        reads.append(Path(path).relative_to(root).as_posix())
        return small_text(path, limit)

    monkeypatch.setattr(workspace, "_small_text", counting)
    with inventory.shared(root):
        metadata.read_metadata(root)
        cpp_sources(root)
    manifests = [r for r in reads if r.endswith("package.xml")]
    assert sorted(manifests) == ["src/driver_cpp/package.xml", "src/legacy_nav/package.xml",
                                 "src/talker_py/package.xml"]
