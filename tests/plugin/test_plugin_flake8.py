"""The flake8 adapter, run in-process on the fake analysis: per-file findings, flake8's filters, options."""
from __future__ import annotations

from pathlib import Path

import pytest
import flake8
from flake8.main.cli import main as flake8_main

from .conftest import EXPECTED_STANDARD, analyses, parse_flake8, write_tree

FLAKE8_MAJOR = int(flake8.__version__.split(".")[0])


def flake8_in_process(args: list[str], cwd: Path, monkeypatch: pytest.MonkeyPatch,
                      capsys: pytest.CaptureFixture[str]) -> tuple[int, str]:
    monkeypatch.chdir(cwd)
    try:
        status = flake8_main(["--jobs", "1", *args])  # flake8 >= 5 returns the status
    except SystemExit as exit_info:  # flake8 4 exits
        status = exit_info.code
    return int(status or 0), capsys.readouterr().out


@pytest.fixture
def run(monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]):
    return lambda args, cwd: flake8_in_process(args, cwd, monkeypatch, capsys)


def test_each_finding_is_reported_in_its_own_file(fake_engine: Path, workspace: Path, run) -> None:
    status, out = run(["--isolated", "--select", "ROS", "."], workspace)
    assert parse_flake8(out) == EXPECTED_STANDARD
    assert status == 1
    assert len(analyses(fake_engine)) == 1


def test_one_file_passed_still_sees_the_whole_workspace(fake_engine: Path, workspace: Path, run) -> None:
    # '/chatter' is subscribed in listener.py but published in the other package
    _, out = run(["--isolated", "src/pkg_b/pkg_b/listener.py"], workspace)
    assert parse_flake8(out) == [("src/pkg_b/pkg_b/listener.py", 7, 10, "ROS003")]


@pytest.mark.parametrize("options, kept", [
    (["--extend-ignore", "ROS002"], {"ROS001", "ROS003"}),
    (["--select", "ROS003"], {"ROS003"}),
    (["--per-file-ignores", "src/pkg_a/*:ROS001"], {"ROS002", "ROS003"}),
    (["--disable-noqa"], {"ROS001", "ROS002", "ROS003", "ROS003/6"}),
])
def test_flake8_selection_and_noqa_apply_to_ros_codes(fake_engine: Path, workspace: Path, run,
                                                      options: list[str], kept: set[str]) -> None:
    _, out = run(["--isolated", *options, "."], workspace)
    found = {code if line != 6 or code != "ROS003" else "ROS003/6" for _, line, _, code in parse_flake8(out)}
    assert found == kept


@pytest.fixture
def unresolved(tmp_path: Path) -> Path:
    return write_tree(tmp_path / "ws2", {
        "src/p/package.xml": "",
        "src/p/p/n.py": """\
            from std_msgs.msg import String


            def make(node, topic):
                node.create_publisher(String, topic, 10)
            """,
    })


@pytest.mark.parametrize("options, reported", [
    ([], False),
    (["--select", "ROS"], False),
    (["--extend-select", "ROS010"], True),
    (["--select", "ROS01"], True),
    pytest.param(["--enable-extensions", "ROS010"], True, marks=pytest.mark.skipif(
        FLAKE8_MAJOR >= 5, reason="flake8 >= 5 hides --enable-extensions from plugins (config file only)")),
])
def test_ros010_is_off_unless_selected_specifically(fake_engine: Path, unresolved: Path, run,
                                                    options: list[str], reported: bool) -> None:
    _, out = run(["--isolated", *options, "."], unresolved)
    assert parse_flake8(out) == ([("src/p/p/n.py", 5, 10, "ROS010")] if reported else [])


def test_ros010_opt_in_from_the_config_file(fake_engine: Path, unresolved: Path, run) -> None:
    (unresolved / "tox.ini").write_text("[flake8]\nenable-extensions = ROS010\n")
    _, out = run(["--config", "tox.ini", "."], unresolved)
    assert [row[3] for row in parse_flake8(out)] == ["ROS010"]


def test_external_topics_from_config_environment_and_command_line(fake_engine: Path, workspace: Path, run,
                                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    def codes(args: list[str]) -> set[str]:
        return {row[3] for row in parse_flake8(run(args, workspace)[1])}

    (workspace / "setup.cfg").write_text("[flake8]\nrosgraph-external-topics = orphan, /other\n")
    assert codes(["--config", "setup.cfg", "."]) == {"ROS002", "ROS003"}
    monkeypatch.setenv("ROSGRAPH_EXTERNAL_TOPICS", "/nobody")
    assert codes(["--isolated", "."]) == {"ROS001", "ROS002"}
    assert codes(["--isolated", "--rosgraph-external-topics", "/orphan", "."]) == {"ROS002", "ROS003"}


def test_explicit_root_narrows_the_workspace(fake_engine: Path, workspace: Path, run) -> None:
    _, out = run(["--isolated", "--rosgraph-root", "src/pkg_a", "."], workspace)
    assert parse_flake8(out) == [("src/pkg_a/pkg_a/talker.py", 5, 10, "ROS001"),
                                 ("src/pkg_a/pkg_a/talker.py", 6, 10, "ROS001"),
                                 ("src/pkg_a/pkg_a/talker.py", 7, 10, "ROS002")]


def test_internal_error_becomes_one_ros000(fake_engine: Path, workspace: Path, run) -> None:
    (workspace / "src/pkg_b/pkg_b/broken.py").write_text("# FAKE_CRASH\n")
    status, out = run(["--isolated", "."], workspace)
    rows = parse_flake8(out)
    assert [row[1:] for row in rows] == [(1, 1, "ROS000")]
    assert "fake analysis crashed" in out and "--rosgraph-debug" in out
    assert status == 1


def test_debug_option_reraises(fake_engine: Path, workspace: Path, run) -> None:
    (workspace / "src/pkg_b/pkg_b/broken.py").write_text("# FAKE_CRASH\n")
    with pytest.raises(RuntimeError, match="fake analysis crashed"):
        run(["--isolated", "--rosgraph-debug", "."], workspace)


def test_analysis_error_diagnostics_surface_once(fake_engine: Path, workspace: Path, run,
                                                 monkeypatch: pytest.MonkeyPatch) -> None:
    import rosgraph_fakes
    from flake8_rosgraph.graph.model import Diagnostic

    def with_error(root, stub_files=(), interface_dirs=(), buffers=(), *_cache_parts):
        graph = rosgraph_fakes.build_graph(root, stub_files, interface_dirs, buffers)
        graph.diagnostics.append(Diagnostic("stubs/x.toml", 3, "stub: bad effect", "error"))
        graph.diagnostics.append(Diagnostic("src/a.py", 1, "cannot parse", "warning"))
        return graph

    import sys
    monkeypatch.setattr(sys.modules["flake8_rosgraph.analysis"], "build_graph", with_error)
    _, out = run(["--isolated", "--select", "ROS000", "."], workspace)
    assert out.count("ROS000") == 1
    assert "stubs/x.toml:3: stub: bad effect" in out and "cannot parse" not in out


def test_files_outside_any_ros_workspace_are_quiet(fake_engine: Path, tmp_path: Path, run) -> None:
    plain = write_tree(tmp_path / "plain", {"tool.py": "print('hello')\n"})
    status, out = run(["--isolated", "--select", "ROS", "tool.py"], plain)
    assert (status, out) == (0, "")


def test_a_second_run_in_the_same_process_reports_the_edited_workspace(fake_engine: Path, workspace: Path,
                                                                         run) -> None:
    """The checker keeps per-report indexes and the last file's report between calls: a new
    run (an editor's language server runs flake8 again in one process) on the same file must
    not reuse them."""
    listener = ["--isolated", "--select", "ROS", "src/pkg_b/pkg_b/listener.py"]
    _, first = run(listener, workspace)
    assert parse_flake8(first) == [("src/pkg_b/pkg_b/listener.py", 7, 10, "ROS003")]
    talker = workspace / "src/pkg_a/pkg_a/talker.py"
    # The talker publishes '/nobody' now: the listener's subscription is heard.
    talker.write_text(talker.read_text(encoding="utf-8") + "    node.create_publisher(String, 'nobody', 10)\n",
                      encoding="utf-8")
    _, second = run(listener, workspace)
    assert parse_flake8(second) == []
    assert len(analyses(fake_engine)) == 2
