"""Unit tests: package index, YAML reader, $(…) substitutions, parameter-file sections, namespaces."""
from __future__ import annotations

import pytest

from flake8_rosgraph.launch.actions import Join, PkgShare, Text, ThisDir, Unknown, Var
from flake8_rosgraph.launch.execute import prefix_namespace
from flake8_rosgraph.launch.frontend_subst import parse_substitutions
from flake8_rosgraph.launch.packages import find_packages
from flake8_rosgraph.launch.param_files import read_param_file
from flake8_rosgraph.launch.yaml_reader import YamlError, read_yaml


def test_packages_and_executables_are_read_statically(ws):
    index = find_packages(ws.root)
    assert sorted(index.packages) == ["demo_bringup", "demo_cpp", "demo_py"]
    demo = index.packages["demo_py"]
    assert (demo.path, demo.build_type, demo.complete) == ("src/demo_py", "ament_python", True)
    assert {n: (e.module, e.function) for n, e in demo.executables.items()} == {
        "talker": ("demo_py.talker", "main"),      # package_name + '.talker:main'
        "listener": ("demo_py.listener", "main"),  # f-string
        "monitor": ("demo_py.monitor", "main"),
    }
    cpp = index.packages["demo_cpp"]
    assert (cpp.build_type, sorted(cpp.executables), cpp.executables["relay"].language) == \
        ("ament_cmake", ["relay"], "cpp")


def test_setup_py_hiding_entry_points_makes_the_package_incomplete(tmp_path):
    pkg = tmp_path / "hidden"
    pkg.mkdir()
    (pkg / "package.xml").write_text("<package><name>hidden</name></package>")
    (pkg / "setup.py").write_text("from setuptools import setup\nsetup(**load_config())\n")
    (pkg / "setup.cfg").write_text("[options.entry_points]\nconsole_scripts =\n    a = hidden.a:main\n")
    package = find_packages(tmp_path).packages["hidden"]
    assert package.complete is False


def test_setup_cfg_entry_points(tmp_path):
    pkg = tmp_path / "cfg"
    pkg.mkdir()
    (pkg / "package.xml").write_text("<package><name>cfg</name></package>")
    (pkg / "setup.cfg").write_text("[options.entry_points]\nconsole_scripts =\n    a = cfg.a:main\n")
    package = find_packages(tmp_path).packages["cfg"]
    assert (package.build_type, package.executables["a"].module) == ("ament_python", "cfg.a")


YAML = """\
# comment
node:            # trailing comment
  ros__parameters:
    rate: 5.0
    name: 'it''s'
    list: [1, "two", {k: v}]
    nested:
      deep: true
    seq:
    - a
    - b: 1
      c: ~
    hex: 0x1F
    text: |
      line one
      line two
"""


def test_yaml_reader_values_and_lines():
    doc = read_yaml(YAML)
    assert doc.plain() == {"node": {"ros__parameters": {
        "rate": 5.0, "name": "it's", "list": [1, "two", {"k": "v"}], "nested": {"deep": True},
        "seq": ["a", {"b": 1, "c": None}], "hex": 31, "text": "line one\nline two\n"}}}
    params = doc.value["node"].value["ros__parameters"]
    assert params.key_lines["rate"] == 4
    assert params.key_lines["hex"] == 13


@pytest.mark.parametrize("text", ["a: [1, 2", "a:\n\tb: 1", "a: 'open", "a: 1\n b: 2"])
def test_yaml_reader_rejects_what_it_cannot_read(text):
    with pytest.raises(YamlError):
        read_yaml(text)


def test_substitutions():
    assert parse_substitutions("plain") == Text("plain")
    assert parse_substitutions("$(var robot)") == Var("robot")
    assert parse_substitutions("$(find-pkg-share $(var pkg))/config/x.yaml") == \
        Join((PkgShare(Var("pkg")), Text("/config/x.yaml")))
    assert parse_substitutions("$(dirname)/a.xml") == Join((ThisDir(), Text("/a.xml")))
    assert isinstance(parse_substitutions("$(env HOME)"), Unknown)
    assert isinstance(parse_substitutions("$(var x"), Unknown)


def test_parameter_file_sections_match_like_rcl(tmp_path):
    (tmp_path / "p.yaml").write_text(
        "/**:\n  ros__parameters:\n    a: 1\n"
        "robot:\n  base:\n    ros__parameters:\n      b: {c: 2}\n"
        "/*/cam:\n  ros__parameters:\n    d: 3\n")
    sections = read_param_file(tmp_path, "p.yaml")
    assert [(s.pattern, [(n, v, loc.line) for n, v, loc in s.settings]) for s in sections] == [
        ("/**", [("a", 1, 3)]), ("/robot/base", [("b.c", 2, 7)]), ("/*/cam", [("d", 3, 10)])]
    every, base, cam = sections
    assert every.matches("/x") and every.matches("/a/b/c")
    assert base.matches("/robot/base") and not base.matches("/base")
    assert cam.matches("/r1/cam") and not cam.matches("/cam") and not cam.matches("/a/b/cam")


@pytest.mark.parametrize("base, ns, expected", [
    (None, None, None), (None, "a", "/a"), ("/r1", None, "/r1"), ("/r1", "a", "/r1/a"),
    ("/r1", "/abs", "/abs"), ("/", "a", "/a"),
])
def test_prefix_namespace_like_launch_ros(base, ns, expected):
    assert prefix_namespace(base, ns) == expected


def test_cmake_executables_under_other_names_are_known(tmp_path):
    """Wrappers of add_executable, renamed outputs and component executables are executables too."""
    pkg = tmp_path / "camera_tools"
    pkg.mkdir()
    (pkg / "package.xml").write_text("<package><name>camera_tools</name>"
                                     "<buildtool_depend>ament_cmake_auto</buildtool_depend></package>")
    (pkg / "CMakeLists.txt").write_text(
        "cmake_minimum_required(VERSION 3.8)\n"
        "project(camera_tools)\n"
        "ament_auto_add_executable(publisher_node src/publisher_node.cpp)\n"
        "ament_auto_add_executable(rotate_bin src/rotate.cpp)\n"
        "set_target_properties(rotate_bin PROPERTIES OUTPUT_NAME ${PROJECT_NAME}_rotate)\n"
        "rclcpp_components_register_node(resize_component PLUGIN \"camera_tools::Resize\"\n"
        "  EXECUTABLE resize_node)\n"
        "add_executable(${PROJECT_NAME}_checker src/checker.cpp)\n"
        "if(BUILD_TESTING)\n"
        "  ament_add_gtest_executable(test_rotate_live test/test_rotate_live.cpp)\n"
        "endif()\n"
        "add_executable(${TOOL_NAME} src/tool.cpp)\n"
        "install(PROGRAMS scripts/calibrate.py DESTINATION lib/${PROJECT_NAME})\n")
    package = find_packages(tmp_path).packages["camera_tools"]
    assert sorted(package.executables) == ["calibrate.py", "camera_tools_checker", "camera_tools_rotate",
                                           "publisher_node",
                                           "resize_node", "rotate_bin", "test_rotate_live"]
    assert package.complete is False  # ${TOOL_NAME}: the list may hold more


def test_cmake_executable_named_by_a_literal_variable(tmp_path):
    """``set(EXEC_NAME "fake_node")`` then ``add_executable(${EXEC_NAME} ...)`` (turtlebot3's
    packages) names the executable, so the list is complete and a launch file's typo is ROS201;
    a variable set to a list, to another variable or to two different words stays unknown."""
    pkg = tmp_path / "fake_base"
    (pkg / "src").mkdir(parents=True)
    (pkg / "src" / "fake_node.cpp").write_text("int main() {}\n")
    (pkg / "package.xml").write_text("<package><name>fake_base</name></package>")
    (pkg / "CMakeLists.txt").write_text(
        "project(fake_base)\n"
        "set(EXEC_NAME \"fake_node\")\n"
        "add_executable(${EXEC_NAME} src/fake_node.cpp)\n"
        "install(TARGETS ${EXEC_NAME} DESTINATION lib/${PROJECT_NAME})\n")
    package = find_packages(tmp_path).packages["fake_base"]
    assert sorted(package.executables) == ["fake_node"] and package.complete
    assert package.executables["fake_node"].sources == ("fake_base/src/fake_node.cpp",)
    for unknown in ("set(EXEC_NAME a b)", "set(EXEC_NAME ${OTHER})", "set(EXEC_NAME a)\nset(EXEC_NAME b)",
                    "set(EXEC_NAME a CACHE STRING doc)"):
        (pkg / "CMakeLists.txt").write_text(f"project(fake_base)\n{unknown}\nadd_executable(${{EXEC_NAME}} x.cpp)\n")
        assert find_packages(tmp_path).packages["fake_base"].complete is False, unknown


def test_cmake_installed_scripts_take_their_rename(tmp_path):
    """``install(PROGRAMS x.py DESTINATION lib/${PROJECT_NAME} RENAME x)`` installs the script
    under the new name (tts_ros: 'tts_node.py' as 'tts_node'); without RENAME the file name."""
    pkg = tmp_path / "voice"
    (pkg / "voice").mkdir(parents=True)
    (pkg / "voice" / "speak_node.py").write_text("import rclpy\n")
    (pkg / "package.xml").write_text("<package><name>voice</name></package>")
    (pkg / "CMakeLists.txt").write_text(
        "project(voice)\n"
        "install(PROGRAMS voice/speak_node.py DESTINATION lib/${PROJECT_NAME} RENAME speak_node)\n"
        "install(PROGRAMS voice/speak_node.py DESTINATION lib/${PROJECT_NAME})\n")
    package = find_packages(tmp_path).packages["voice"]
    assert sorted(package.executables) == ["speak_node", "speak_node.py"]
    assert package.executables["speak_node"].script == "voice/voice/speak_node.py"


def test_cmake_subdirectories_add_their_executables(tmp_path):
    """``add_subdirectory`` is followed (moveit2_tutorials builds every example in its own folder):
    its targets are the package's, with the package's PROJECT_NAME; a folder named by a variable,
    or one that is not there, leaves the list incomplete; a folder outside the workspace is not read."""
    pkg = tmp_path / "arm_tutorials"
    (pkg / "examples" / "planning").mkdir(parents=True)
    (pkg / "examples" / "servo" / "nested").mkdir(parents=True)
    (pkg / "package.xml").write_text("<package><name>arm_tutorials</name></package>")
    (pkg / "CMakeLists.txt").write_text(
        "project(arm_tutorials)\n"
        "add_subdirectory(examples/planning)\n"
        "add_subdirectory(examples/servo)\n")
    (pkg / "examples" / "planning" / "CMakeLists.txt").write_text(
        "add_executable(planning_tutorial src/planning_tutorial.cpp)\n"
        "install(PROGRAMS scripts/plan.py DESTINATION lib/${PROJECT_NAME})\n")
    (pkg / "examples" / "servo" / "CMakeLists.txt").write_text(
        "add_executable(servo_tutorial servo_tutorial.cpp)\nadd_subdirectory(nested)\n"
        "add_subdirectory(examples/servo)\n")  # not there: the list may hold more
    (pkg / "examples" / "servo" / "servo_tutorial.cpp").write_text("int main() { return 0; }\n")
    (pkg / "examples" / "servo" / "nested" / "CMakeLists.txt").write_text(
        "add_executable(${PROJECT_NAME}_teleop teleop.cpp)\n")
    package = find_packages(tmp_path).packages["arm_tutorials"]
    assert sorted(package.executables) == ["arm_tutorials_teleop", "plan.py", "planning_tutorial", "servo_tutorial"]
    assert package.executables["servo_tutorial"].sources == ("arm_tutorials/examples/servo/servo_tutorial.cpp",)
    assert package.complete is False
    (pkg / "examples" / "servo" / "CMakeLists.txt").write_text("add_executable(servo_tutorial servo_tutorial.cpp)\n")
    assert find_packages(tmp_path).packages["arm_tutorials"].complete is True
    (pkg / "CMakeLists.txt").write_text("project(arm_tutorials)\nadd_subdirectory(${EXAMPLES_DIR})\n")
    assert find_packages(tmp_path).packages["arm_tutorials"].complete is False
    outside = tmp_path.parent / (tmp_path.name + "_outside")
    outside.mkdir(exist_ok=True)
    (outside / "CMakeLists.txt").write_text("add_executable(stray stray.cpp)\n")
    (pkg / "CMakeLists.txt").write_text(f"project(arm_tutorials)\nadd_subdirectory(../../{outside.name})\n")
    package = find_packages(pkg).packages["arm_tutorials"]
    assert "stray" not in package.executables and package.complete is False
