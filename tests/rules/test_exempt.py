"""The exempt list: built-in names, user names, and the wildcard syntax."""
import pytest

from flake8_rosgraph.rules.exempt import BUILTIN_EXEMPT, ExemptNames


@pytest.mark.parametrize("name", ["/rosout", "/parameter_events", "/tf", "/tf_static", "/clock", "/diagnostics",
                                  "/robot_description", "/joint_states", "/initialpose", "/goal_pose",
                                  "/camera/get_parameters", "/a/b/c/set_parameters_atomically",
                                  "/talker/get_type_description", "/lc_talker/transition_event"])
def test_builtin(name):
    assert name in ExemptNames.build()


@pytest.mark.parametrize("name", ["/cmd_vel", "/tf2", "/robot/tf", "/get_parameters", "/camera/get_parameters_x",
                                  "/scan", None])
def test_not_builtin(name):
    assert name not in ExemptNames.build()


def test_every_builtin_entry_says_why():
    assert all(pattern.startswith("/") and why for pattern, why in BUILTIN_EXEMPT)


def test_user_names_get_a_leading_slash_and_blanks_are_ignored():
    exempt = ExemptNames.build(["cmd_vel", " /odom ", ""])
    assert "/cmd_vel" in exempt and "/odom" in exempt and "/" not in exempt


def test_single_star_stays_within_a_component():
    exempt = ExemptNames.build(["/robot*/scan", "/cam?/image"])
    assert "/robot1/scan" in exempt and "/robot/scan" in exempt and "/cam1/image" in exempt
    assert "/robot1/x/scan" not in exempt and "/cam12/image" not in exempt


def test_double_star_crosses_components():
    exempt = ExemptNames.build(["/sim/**"])
    assert "/sim/a" in exempt and "/sim/a/b/c" in exempt and "/simx" not in exempt


def test_regex_characters_are_literal():
    exempt = ExemptNames.build(["/a.b", "/c+"])
    assert "/a.b" in exempt and "/axb" not in exempt and "/c+" in exempt and "/cc" not in exempt
