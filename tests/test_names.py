"""ROS 2 name validation and expansion against the behaviour of rcl and rmw.

The table cases follow the unit tests of the C libraries (cases re-typed here,
expected results read off the C sources):
rmw/test/test_validate_node_name.cpp, rmw/test/test_validate_namespace.cpp,
rmw/test/test_validate_full_topic_name.cpp (ros2/rmw),
rcl/test/rcl/test_validate_topic_name.cpp, rcl/test/rcl/test_expand_topic_name.cpp,
rcl/test/rcl/test_remap.cpp (ros2/rcl).
"""
from __future__ import annotations

import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from flake8_rosgraph.graph.names import (
    HIDDEN_PREFIX,
    NAMESPACE_MAX_LENGTH,
    NODE_NAME_MAX_LENGTH,
    TOPIC_MAX_NAME_LENGTH,
    NameCheck,
    RemapRule,
    built_at_root,
    edit_distance,
    expand_topic_name,
    first_remap_match,
    fqn,
    is_hidden,
    normalize_namespace,
    rebuild_in_namespace,
    validate_full_topic_name,
    validate_namespace,
    validate_node_name,
    validate_parameter_name,
    validate_topic_name,
)


def assert_fails(check: NameCheck, reason_part: str, index: int | None) -> None:
    assert not check.ok
    assert check.reason is not None and reason_part in check.reason, check.reason
    assert check.index == index


# --- rmw_validate_node_name (rmw/test/test_validate_node_name.cpp) -------------------------------

@pytest.mark.parametrize("name", ["nodename", "node_name", "_hidden", "N0de", "a" * NODE_NAME_MAX_LENGTH])
def test_valid_node_names(name):
    assert validate_node_name(name) == NameCheck(True, None, None)


@pytest.mark.parametrize(("name", "reason", "index"), [
    ("", "empty", 0),
    ("node/name", "contains '/'", 4),
    ("node_{name}", "contains '{'", 5),
    ("~node_name", "contains '~'", 0),
    ("with spaces", "contains ' '", 4),
    ("with.periods", "contains '.'", 4),
    ("42node", "starts with a digit", 0),
    ("nodé", "contains 'é'", 3),            # ASCII only, like rcutils_isalnum_no_locale
    ("0" * (NODE_NAME_MAX_LENGTH + 1), "starts with a digit", 0),  # length is checked last
    ("a" * (NODE_NAME_MAX_LENGTH + 1), "longer than 255", NODE_NAME_MAX_LENGTH - 1),
])
def test_invalid_node_names(name, reason, index):
    assert_fails(validate_node_name(name), reason, index)


# --- rmw_validate_full_topic_name (rmw/test/test_validate_full_topic_name.cpp) -------------------

@pytest.mark.parametrize("name", ["/basename_only", "/with_one/namespace", "/_private/thing", "/a1/b_2"])
def test_valid_full_topic_names(name):
    assert validate_full_topic_name(name).ok


@pytest.mark.parametrize(("name", "reason", "index"), [
    ("", "empty", 0),
    ("not_absolute", "not absolute", 0),
    ("not/absolute", "not absolute", 0),
    ("/ends/with/", "ends with '/'", 10),
    ("/", "ends with '/'", 0),
    ("/~/unexpanded_tilde", "contains '~'", 1),
    ("/unexpanded_sub/{node}", "contains '{'", 16),
    ("/question?", "contains '?'", 9),
    ("/with spaces", "contains ' '", 5),
    ("/repeated//slashes", "contains '//'", 10),
    ("/9starts_with_number", "token that starts with a digit", 1),
    ("/starts/42with/number", "token that starts with a digit", 8),
    ("a" * (TOPIC_MAX_NAME_LENGTH + 1), "not absolute", 0),
    ("/" + "a" * (TOPIC_MAX_NAME_LENGTH + 1), "longer than 247", TOPIC_MAX_NAME_LENGTH - 1),
])
def test_invalid_full_topic_names(name, reason, index):
    assert_fails(validate_full_topic_name(name), reason, index)


def test_full_topic_name_length_limit_is_inclusive():
    assert validate_full_topic_name("/" + "a" * (TOPIC_MAX_NAME_LENGTH - 1)).ok
    assert not validate_full_topic_name("/" + "a" * TOPIC_MAX_NAME_LENGTH).ok


# --- rmw_validate_namespace (rmw/test/test_validate_namespace.cpp) -------------------------------

@pytest.mark.parametrize("ns", ["/", "/basename_only", "/with_one/heirarchy"])
def test_valid_namespaces(ns):
    assert validate_namespace(ns).ok


@pytest.mark.parametrize(("ns", "reason", "index"), [
    ("", "empty", 0),
    ("not_absolute", "not absolute", 0),
    ("/ends/with/", "ends with '/'", 10),
    ("/~/unexpanded_tilde", "contains '~'", 1),
    ("/unexpanded_sub/{node}", "contains '{'", 16),
    ("/repeated//slashes", "contains '//'", 10),
    ("/starts/42with/number", "token that starts with a digit", 8),
    ("a" * (NAMESPACE_MAX_LENGTH + 1), "not absolute", 0),
    ("/" + "a" * (NAMESPACE_MAX_LENGTH + 1), "longer than 245", NAMESPACE_MAX_LENGTH - 1),
    # longer than a namespace may be, but still a legal topic name length
    ("/" + "a" * (NAMESPACE_MAX_LENGTH), "longer than 245", NAMESPACE_MAX_LENGTH - 1),
])
def test_invalid_namespaces(ns, reason, index):
    assert_fails(validate_namespace(ns), reason, index)


# --- rcl_validate_topic_name (rcl/test/rcl/test_validate_topic_name.cpp) -------------------------

@pytest.mark.parametrize("name", [
    "foo", "abc123", "_foo", "Foo", "BAR", "~", "foo/bar", "~/foo", "{foo}_bar", "foo/{ping}/bar",
    "foo/_bar", "foo_/bar", "foo_", "/foo", "/bar/baz", "/_private/thing",
    "/public_namespace/_private/thing", "{foo1}", "{foo_bar}", "{_bar}",
    "foo//bar",  # repeated '/' is only caught after expansion
    "~f",        # rcl never inspects the pair (1, 2) of a two-character name
])
def test_valid_unexpanded_topic_names(name):
    assert validate_topic_name(name) == NameCheck(True, None, None)


@pytest.mark.parametrize(("name", "reason", "index"), [
    ("123abc", "starts with a digit", 0),
    ("123", "starts with a digit", 0),
    (" ", "contains ' '", 0),
    ("foo bar", "contains ' '", 3),
    ("/~", "'~' that is not the first character", 1),
    ("~foo", "'~' that is not followed by '/'", 1),
    ("foo~", "'~' that is not the first character", 3),
    ("foo~/bar", "'~' that is not the first character", 3),
    ("foo/~bar", "'~' that is not the first character", 4),
    ("foo/~/bar", "'~' that is not the first character", 4),
    ("foo/", "ends with '/'", 3),
    ("~/", "ends with '/'", 1),
    ("", "empty", 0),
    ("foo/123bar", "token that starts with a digit", 4),
    ("foo/bar}/baz", "unmatched '}'", 7),
    ("foo/{bar", "unmatched '{'", 4),
    ("{$}", "substitution that contains '$'", 1),
    ("{{bar}_baz}", "nested '{'", 1),
    ("foo/{bar/baz}", "substitution that contains '/'", 8),
    ("{1foo}", "substitution that starts with a digit", 1),
])
def test_invalid_unexpanded_topic_names(name, reason, index):
    assert_fails(validate_topic_name(name), reason, index)


# --- rcl_expand_topic_name (rcl/test/rcl/test_expand_topic_name.cpp) -----------------------------

@pytest.mark.parametrize(("name", "node", "ns", "expected"), [
    ("/chatter", "my_node", "/my_ns", "/chatter"),
    ("chatter", "my_node", "/my_ns", "/my_ns/chatter"),
    ("{node}/chatter", "my_node", "/my_ns", "/my_ns/my_node/chatter"),
    ("/{node}", "my_node", "/my_ns", "/my_node"),
    ("{node}", "my_node", "/my_ns", "/my_ns/my_node"),
    ("{ns}", "my_node", "/my_ns", "/my_ns"),
    ("{namespace}", "my_node", "/my_ns", "/my_ns"),
    ("{namespace}/{node}/chatter", "my_node", "/my_ns", "/my_ns/my_node/chatter"),
    ("ping", "my_node", "/", "/ping"),
    ("ping", "my_node", "/my_ns", "/my_ns/ping"),
    ("/ping", "my_node", "/", "/ping"),
    ("/ping", "my_node", "/my_ns", "/ping"),
    ("~", "my_node", "/", "/my_node"),
    ("~", "my_node", "/my_ns", "/my_ns/my_node"),
    ("~/ping", "my_node", "/", "/my_node/ping"),
    ("~/ping", "my_node", "/my_ns", "/my_ns/my_node/ping"),
    ("{node}/{node}", "n", "/a/b", "/a/b/n/n"),
])
def test_expand_valid(name, node, ns, expected):
    assert expand_topic_name(name, node, ns) == (expected, NameCheck(True, None, None))


def test_expansion_succeeds_but_result_is_invalid():
    # rcl expands "/foo/{namespace}" to "/foo//my_ns"; the rmw check afterwards rejects it.
    expanded, check = expand_topic_name("/foo/{namespace}", "my_node", "/my_ns")
    assert expanded == "/foo//my_ns"
    assert_fails(check, "contains '//'", 5)
    expanded, check = expand_topic_name("{ns}", "my_node", "/")
    assert expanded == "/"
    assert_fails(check, "ends with '/'", 0)
    expanded, check = expand_topic_name("a//b", "n", "/")
    assert expanded == "/a//b"
    assert_fails(check, "contains '//'", 3)


def test_expansion_hits_the_length_limit():
    long_ns = "/" + "n" * 200
    expanded, check = expand_topic_name("t" * 50, "node", long_ns)
    assert expanded == long_ns + "/" + "t" * 50
    assert_fails(check, "longer than 247", TOPIC_MAX_NAME_LENGTH - 1)


@pytest.mark.parametrize(("name", "node", "ns", "reason", "index"), [
    ("white space", "my_node", "/my_ns", "contains ' '", 5),
    ("{node}/chatter", "/invalid_node", "/my_ns", "node name contains '/'", None),
    ("{node}/chatter", "my_node", "white space", "namespace is not absolute", None),
    ("{doesnotexist}", "my_node", "/my_ns", "unknown substitution {doesnotexist}", 0),
    ("{unknown}/test", "bar", "/foo", "unknown substitution {unknown}", 0),
    ("~/{}", "bar", "/foo", "unknown substitution {}", 2),
])
def test_expand_refused(name, node, ns, reason, index):
    expanded, check = expand_topic_name(name, node, ns)
    assert expanded is None
    assert_fails(check, reason, index)


def test_expand_invalid_input_is_reported_before_invalid_node():
    # rcl validates the topic name first, then the node name, then the namespace.
    _, check = expand_topic_name("1abc", "2node", "bad")
    assert_fails(check, "starts with a digit", 0)
    _, check = expand_topic_name("abc", "2node", "bad")
    assert_fails(check, "node name starts with a digit", None)


def test_expand_custom_substitution():
    assert expand_topic_name("{ping}", "my_node", "/my_ns", {"ping": "pong"})[0] == "/my_ns/pong"
    # the built-in substitutions win over the user's map
    assert expand_topic_name("{node}", "my_node", "/my_ns", {"node": "other"})[0] == "/my_ns/my_node"
    expanded, check = expand_topic_name("{a}", "n", "/", {"a": "{a}"})
    assert expanded is None
    assert_fails(check, "value with braces", 0)


# --- rcl_remap_first_match (rcl/test/rcl/test_remap.cpp) -----------------------------------------

def test_remap_rules():
    rules = [RemapRule("/bar/foo", "/foo/bar")]
    assert first_remap_match("/bar/foo", rules, "NodeName", "/") == rules[0]
    assert first_remap_match("/foo/bar", rules, "NodeName", "/") is None
    relative = [RemapRule("foo", "bar")]
    assert first_remap_match("/ns/foo", relative, "NodeName", "/ns") == relative[0]
    assert first_remap_match("/foo", relative, "NodeName", "/ns") is None


def test_remap_rules_with_node_prefix_and_order():
    rules = [
        RemapRule("/foo", "/foo/bar", node="Node1"),
        RemapRule("/foo", "/this_one", node="Node2"),
        RemapRule("/foo", "/bar/foo", node="Node3"),
        RemapRule("/foo", "/fallback"),
        RemapRule("/foo", "/never"),
    ]
    assert first_remap_match("/foo", rules, "Node2", "/").replacement == "/this_one"
    assert first_remap_match("/foo", rules, "Node9", "/").replacement == "/fallback"


def test_remap_rule_that_does_not_expand_is_skipped():
    rules = [RemapRule("{unknown}", "/x"), RemapRule("~/foo", "/y")]
    assert first_remap_match("/ns/me/foo", rules, "me", "/ns").replacement == "/y"


# --- rclpy behaviour -------------------------------------------------------------------------------

@pytest.mark.parametrize(("raw", "normalized"), [
    (None, "/"), ("", "/"), ("/", "/"), ("foo", "/foo"), ("/foo/bar", "/foo/bar"), ("foo/bar", "/foo/bar"),
    ("/foo/", "/foo/"),  # kept: rcl rejects it, the caller must see that
])
def test_normalize_namespace(raw, normalized):
    assert normalize_namespace(raw) == normalized


def test_trailing_slash_namespace_stays_invalid():
    assert_fails(validate_namespace(normalize_namespace("foo/")), "ends with '/'", 4)


@pytest.mark.parametrize(("node", "ns", "expected"), [
    ("talker", "/", "/talker"), ("talker", "/demo", "/demo/talker"), ("x", "/a/b", "/a/b/x"),
])
def test_fqn(node, ns, expected):
    assert fqn(node, ns) == expected


@pytest.mark.parametrize("name", ["rate", "a.b.c", "use_sim_time", "x/y", "1st", " "])
def test_parameter_names_rclpy_accepts(name):
    assert validate_parameter_name(name).ok


def test_empty_parameter_name_is_rejected():
    assert_fails(validate_parameter_name(""), "empty", 0)


@pytest.mark.parametrize(("name", "hidden"), [
    ("/_private/thing", True), ("/public_namespace/_private/thing", True), ("_node", True),
    ("/foo/bar_", False), ("/chatter", False), ("talker", False),
])
def test_is_hidden(name, hidden):
    assert HIDDEN_PREFIX == "_"
    assert is_hidden(name) is hidden


@pytest.mark.parametrize(("a", "b", "limit", "expected"), [
    ("/cmd_vel", "/cmd_vel", 2, 0),
    ("/cmd_vel", "/cmdvel", 2, 1),
    ("kitten", "sitting", 3, 3),
    ("kitten", "sitting", 2, 3),       # capped at limit + 1
    ("", "abc", 5, 3),
    ("abcdef", "a", 2, 3),             # length gap alone exceeds the limit
    ("/scan", "/odom", 1, 2),
])
def test_edit_distance(a, b, limit, expected):
    assert edit_distance(a, b, limit) == expected


def test_edit_distance_rejects_negative_limit():
    with pytest.raises(ValueError):
        edit_distance("a", "b", -1)


# --- properties -----------------------------------------------------------------------------------

TOKEN = st.from_regex(r"[A-Za-z_][A-Za-z0-9_]{0,8}", fullmatch=True)
TOKENS = st.lists(TOKEN, min_size=1, max_size=5)
NAMESPACE = st.lists(TOKEN, max_size=4).map(lambda tokens: "/" + "/".join(tokens))
# Relative and absolute names, private names and {node} substitutions: all expand to valid names.
USER_NAME = st.one_of(
    TOKENS.map("/".join),
    TOKENS.map(lambda t: "/" + "/".join(t)),
    TOKENS.map(lambda t: "~/" + "/".join(t)),
    st.just("~"),
    TOKENS.map(lambda t: "/".join(["{node}", *t])),
    TOKENS.map(lambda t: "/".join([*t, "{node}"])),
    TOKENS.map(lambda t: "/".join(["{ns}", *t])),
)
NAME_TEXT = st.one_of(st.text(max_size=30), st.text(alphabet="ab_1/~{}.é ", max_size=20))
FULL_NAME_RE = re.compile(r"(/[A-Za-z_][A-Za-z0-9_]*)+")
NODE_NAME_RE = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


@given(USER_NAME, TOKEN, NAMESPACE)
def test_names_from_valid_tokens_expand_to_valid_full_names(name, node, ns):
    if name.startswith("{ns}") and ns == "/":
        name = name.replace("{ns}", "{node}", 1)  # "{ns}/x" under the root namespace gives "//x"
    assert validate_topic_name(name).ok
    expanded, check = expand_topic_name(name, node, ns)
    assert check.ok, (name, node, ns, expanded, check)
    assert expanded is not None and FULL_NAME_RE.fullmatch(expanded)
    if not name.startswith("/"):
        assert expanded.startswith(ns)


@given(TOKENS, TOKEN, NAMESPACE)
def test_expanding_a_valid_absolute_name_is_the_identity(tokens, node, ns):
    name = "/" + "/".join(tokens)
    assert expand_topic_name(name, node, ns) == (name, NameCheck(True, None, None))


@given(NAME_TEXT)
def test_full_name_check_agrees_with_the_grammar(text):
    check = validate_full_topic_name(text)
    assert check.ok == (bool(FULL_NAME_RE.fullmatch(text)) and len(text) <= TOPIC_MAX_NAME_LENGTH)
    assert (check.reason is None and check.index is None) if check.ok else (0 <= check.index < max(len(text), 1))


@given(NAME_TEXT)
def test_node_name_and_namespace_checks_agree_with_the_grammar(text):
    assert validate_node_name(text).ok == (bool(NODE_NAME_RE.fullmatch(text)) and len(text) <= 255)
    expected_ns = text == "/" or (bool(FULL_NAME_RE.fullmatch(text)) and len(text) <= NAMESPACE_MAX_LENGTH)
    assert validate_namespace(text).ok == expected_ns


@settings(max_examples=300)
@given(NAME_TEXT, TOKEN, NAMESPACE)
def test_validation_and_expansion_never_raise(text, node, ns):
    check = validate_topic_name(text)
    if not check.ok:
        assert check.index is not None and 0 <= check.index < max(len(text), 1)
    expanded, result = expand_topic_name(text, node, ns)
    if not check.ok:
        assert expanded is None and result == check
    if expanded is not None:
        assert result == validate_full_topic_name(expanded)


def levenshtein(a: str, b: str) -> int:
    """Textbook recursion-free reference, no early exit."""
    previous = list(range(len(b) + 1))
    for i, char_a in enumerate(a, 1):
        current = [i]
        for j, char_b in enumerate(b, 1):
            current.append(min(previous[j] + 1, current[-1] + 1, previous[j - 1] + (char_a != char_b)))
        previous = current
    return previous[-1]


SHORT = st.text(alphabet="abc/_", max_size=8)


@given(SHORT, SHORT, st.integers(min_value=0, max_value=6))
def test_edit_distance_properties(a, b, limit):
    distance = edit_distance(a, b, limit)
    assert distance == edit_distance(b, a, limit)
    assert (distance == 0) == (a == b)
    assert distance == min(levenshtein(a, b), limit + 1)


# --- names built from the node's namespace -----------------------------------------------
@pytest.mark.parametrize(("raw", "namespace", "built"), [
    ("//cmd", "/", True),          # get_namespace() + '/cmd' in the root namespace
    ("/cmd", "/", False),          # absolute, written or built safely
    ("cmd", "/", False),
    ("//cmd", "/robot1", False),   # not what the namespace gives there
    ("//cmd", None, False),
    (None, "/", False),
])
def test_built_at_root(raw, namespace, built):
    assert built_at_root(raw, namespace) is built


@pytest.mark.parametrize(("raw", "code_ns", "launch_ns", "rebuilt"), [
    ("//cmd", "/", "/robot1", "/robot1/cmd"),
    ("//cmd", "/", "/fleet/robot1", "/fleet/robot1/cmd"),
    ("//cmd", "/", "/", "//cmd"),              # still the root: still broken
    ("//cmd", "/", None, None),                # the launch namespace is unknown
    ("/cmd", "/", "/robot1", "/cmd"),          # absolute names stay
    ("cmd", "/", "/robot1", "cmd"),            # relative ones are expanded later anyway
    ("/robot1/cmd", "/robot1", "/robot2", "/robot1/cmd"),
])
def test_rebuild_in_namespace(raw, code_ns, launch_ns, rebuilt):
    assert rebuild_in_namespace(raw, code_ns, launch_ns) == rebuilt


def test_known_suffix_is_what_every_expansion_ends_with():
    from flake8_rosgraph.graph.names import known_suffix

    assert known_suffix("amcl_pose") == "/amcl_pose"
    assert known_suffix("scan/filtered") == "/scan/filtered"
    assert known_suffix("~/status") == "/status"
    assert known_suffix("/odom") is None        # absolute: known, or not a name at all
    assert known_suffix("~") is None
    assert known_suffix("{node}/state") is None
    assert known_suffix(None) is None
