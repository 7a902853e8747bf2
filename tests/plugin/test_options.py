"""Settings from flake8 options and environment variables; the off-by-default opt-in."""
from __future__ import annotations

from pathlib import Path

import pytest

from flake8_rosgraph.options import CodeFilter, Settings
from flake8_rosgraph.rules import RULES


def test_environment_fills_what_flake8_was_not_given() -> None:
    env = {"ROSGRAPH_ROOT": "/ws", "ROSGRAPH_STUBS": "a.toml, b.toml", "ROSGRAPH_EXTERNAL_TOPICS": "/fix,gps/*",
           "ROSGRAPH_SARIF": "out.sarif", "ROSGRAPH_CACHE_DIR": "/tmp/c", "ROSGRAPH_DEBUG": "yes"}
    settings = Settings.resolve({}, env)
    assert settings == Settings(root=Path("/ws"), stub_files=(Path("a.toml"), Path("b.toml")),
                                external_topics=("/fix", "gps/*"), sarif=Path("out.sarif"),
                                cache_dir=Path("/tmp/c"), debug=True)


def test_flake8_options_win_over_the_environment() -> None:
    env = {"ROSGRAPH_ROOT": "/env", "ROSGRAPH_EXTERNAL_TOPICS": "/from_env"}
    settings = Settings.resolve({"root": "/cli", "external_topics": ["/from_cli"]}, env)
    assert settings.root == Path("/cli")
    assert settings.external_topics == ("/from_cli",)


@pytest.mark.parametrize("value, debug", [("1", True), ("true", True), ("ON", True), ("0", False), ("", False)])
def test_debug_environment_values(value: str, debug: bool) -> None:
    assert Settings.resolve({}, {"ROSGRAPH_DEBUG": value}).debug is debug


@pytest.mark.parametrize("selectors, opted_in", [
    ([], False),
    (["E", "F", "W", "C90"], False),   # flake8 4's default --select
    (["ROS"], False),                  # the plugin's family: default rules only
    (["ROS0"], False),                 # the graph-wiring family
    (["ROS01"], True),                 # names ROS010 and no default-enabled rule
    (["ROS010"], True),
    (["ros010"], True),
    (["E", "ROS010"], True),
    (["ROS011"], False),
])
def test_ros010_needs_a_selector_that_names_it_specifically(selectors: list[str], opted_in: bool) -> None:
    codes = CodeFilter.build(selectors, RULES)
    assert codes("ROS010") is opted_in
    assert codes("ROS001") and codes("ROS000") and codes("E501")
